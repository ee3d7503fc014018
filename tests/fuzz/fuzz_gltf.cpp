// libFuzzer harness: any bytes as a glTF file through load_scene (tinygltf, our conversion and
// scene validation). A LoadError is the right answer to bad input; any other exception, a crash
// or a sanitizer report is a finding.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "fuzz_folder.h"
#include "load_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const radiant::fuzz::FuzzFolder folder("gltf");
  std::string bytes(reinterpret_cast<const char*>(data), size);
  // The loader tells binary from text by the magic, not the extension; name it as a user would.
  std::filesystem::path file = folder.path / (bytes.compare(0, 4, "glTF") == 0 ? "fuzz.glb" : "fuzz.gltf");
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
  radiant::LoadOptions options;
  options.max_memory_bytes = radiant::fuzz::fuzz_memory_limit;
  try {
    radiant::load_scene(file.string(), options);
  } catch (const radiant::LoadError&) {
  }
  std::filesystem::remove(file);
  return 0;
}
