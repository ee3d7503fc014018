// The targets that load a scene file: `.scene`, glTF, and the two that also render what loads
// (any scene file, and an OBJ with its MTL and texture).
#include <string_view>
#include <vector>

#include "fuzz_folder.h"
#include "fuzz_support.h"
#include "load_scene.h"

namespace radiant::fuzz {

namespace {

namespace fs = std::filesystem;

LoadOptions fuzz_load_options() {
  LoadOptions options;
  options.max_memory_bytes = fuzz_memory_limit;
  return options;
}

bool starts_with(const std::string& bytes, std::string_view prefix) { return bytes.compare(0, prefix.size(), prefix) == 0; }

// The name a user would give these bytes: the loader tells GLB from JSON by the magic, and JSON
// from `.scene` by the extension.
std::string scene_file_name(const std::string& bytes) {
  if (starts_with(bytes, "glTF")) return "fuzz.glb";
  size_t first = bytes.find_first_not_of(" \t\r\n");
  return first != std::string::npos && bytes[first] == '{' ? "fuzz.gltf" : "fuzz.scene";
}

// Splits the obj target's input at its separator lines into the OBJ, the MTL and the texture.
std::vector<std::string_view> split_obj_input(std::string_view bytes) {
  std::vector<std::string_view> parts;
  while (parts.size() < 2) {
    size_t at = bytes.find(obj_part_separator);
    if (at == std::string_view::npos) break;
    parts.push_back(bytes.substr(0, at));
    bytes.remove_prefix(at + obj_part_separator.size());
  }
  parts.push_back(bytes);
  parts.resize(3);
  return parts;
}

}  // namespace

FuzzOutcome run_scene_target(const fs::path& folder, const std::string& bytes) {
  InputFiles files(folder);
  fs::path file = files.write("fuzz.scene", bytes);
  return outcome_of([&] { load_scene(file.string(), fuzz_load_options()); });
}

FuzzOutcome run_gltf_target(const fs::path& folder, const std::string& bytes) {
  InputFiles files(folder);
  fs::path file = files.write(starts_with(bytes, "glTF") ? "fuzz.glb" : "fuzz.gltf", bytes);
  return outcome_of([&] { load_scene(file.string(), fuzz_load_options()); });
}

FuzzOutcome run_render_target(const fs::path& folder, const std::string& bytes) {
  InputFiles files(folder);
  fs::path file = files.write(scene_file_name(bytes), bytes);
  return outcome_of([&] { render_tiny(load_scene(file.string(), fuzz_load_options())); });
}

FuzzOutcome run_obj_target(const fs::path& folder, const std::string& bytes) {
  InputFiles files(folder);
  std::vector<std::string_view> parts = split_obj_input(bytes);
  fs::path obj = files.write("fuzz.obj", parts[0]);
  files.write("fuzz.mtl", parts[1]);
  files.write("texture.png", parts[2]);
  return outcome_of([&] { render_tiny(load_scene(obj.string(), fuzz_load_options())); });
}

}  // namespace radiant::fuzz
