// libFuzzer harness: any bytes through the `.scene` parser and scene validation. A LoadError is
// the right answer to bad input; any other exception, a crash or a sanitizer report is a finding.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "fuzz_folder.h"
#include "load_scene.h"
#include "scene/validate.h"
#include "scene_format/scene_format_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const radiant::fuzz::FuzzFolder folder("scene");
  radiant::LoadOptions options;
  options.max_memory_bytes = radiant::fuzz::fuzz_memory_limit;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    radiant::SceneDesc scene = radiant::load_scene_format(in, "fuzz.scene", folder.path.string(), options);
    scene.source_path = "fuzz.scene";  // as load_scene does before validating
    radiant::validate_scene(scene);
  } catch (const radiant::LoadError&) {
  }
  return 0;
}
