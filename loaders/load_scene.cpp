#include "load_scene.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "file_access.h"
#include "gltf/gltf_loader.h"
#include "message_text.h"
#include "obj/obj_loader.h"
#include "output/file_extension.h"
#include "scene/scene_memory.h"
#include "scene/validate.h"
#include "scene_format/scene_format_loader.h"

namespace radiant {

static SceneDesc load_by_extension(const std::string& path, const LoadOptions& options) {
  if (path == "-") return load_scene_format(std::cin, "<stdin>", std::filesystem::current_path().string(), options);
  check_input_file(path, path, options);
  std::string ext = lowercase_extension(path);
  if (ext == ".gltf" || ext == ".glb") return load_gltf(path, options);
  if (!options.material_variant.empty())
    throw LoadError(path + ": material variants (--variant) are a glTF extension (KHR_materials_variants)");
  if (ext == ".obj") return load_obj(path, options);
  if (ext == ".scene") {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw LoadError(path + ": cannot open scene file");
    std::string base = std::filesystem::absolute(path).parent_path().string();
    return load_scene_format(in, path, base, options);
  }
  throw LoadError(path + ": unknown scene format '" + ext + "' (expected .scene, .gltf, .glb or .obj)");
}

// Names the scene by its file, records the files it read and validates it.
static void finish_scene(SceneDesc& scene, const std::string& path, const LoadOptions& options,
                         std::vector<std::string> files_read) {
  scene.source_path = path == "-" ? "<stdin>" : path;
  std::string ext = lowercase_extension(path);
  if (options.animation_time && ext != ".gltf" && ext != ".glb")
    scene.warnings.push_back(scene.source_path + ": --time/--frame/--animation apply to glTF animations only");
  scene.input_files = std::move(files_read);
  validate_scene(scene);
}

// Runs `make` (which loads a scene) with what loading charges given back afterwards, when
// only the scene stays in memory, or on failure.
template <typename Make>
static SceneDesc with_transient_charges(const LoadOptions& options, Make make) {
  MemoryBudget& budget = *options.budget;
  uint64_t used_before = budget.used();
  SceneDesc scene;
  try {
    scene = make();
  } catch (...) {
    budget.release(budget.used() - used_before);
    throw;
  }
  // Loading kept its transient buffers charged (file text, JSON trees, parsed OBJ, decoded
  // copies) until now; what stays in memory is the scene.
  budget.release(budget.used() - used_before);
  charge_load(options, scene_memory_bytes(scene), scene.source_path + ": the loaded scene");
  return scene;
}

SceneDesc load_scene(const std::string& path, const LoadOptions& given) {
  BudgetedLoadOptions budgeted(given);
  std::vector<std::string> files_read;
  budgeted.options.files_read = &files_read;
  const LoadOptions& options = budgeted.options;
  return with_transient_charges(options, [&] {
    SceneDesc scene = load_by_extension(path, options);
    finish_scene(scene, path, options, std::move(files_read));
    return scene;
  });
}

SceneFile read_scene_file(const std::string& path, const LoadOptions& given) {
  LoadOptions options = given;
  SceneFile file;
  file.path = path;
  options.files_read = &file.files_read;
  std::string ext = lowercase_extension(path);
  if (path != "-" && (ext == ".gltf" || ext == ".glb")) {
    check_input_file(path, path, options);
    file.gltf = read_gltf_document(path, options);
  } else {
    file.scene = std::make_shared<const SceneDesc>(load_by_extension(path, options));
  }
  return file;
}

SceneFileChoices scene_file_choices(const SceneFile& file) {
  return file.gltf ? gltf_choices(*file.gltf) : SceneFileChoices{};
}

SceneDesc scene_from_file(SceneFile& file, const LoadOptions& given) {
  BudgetedLoadOptions budgeted(given);
  const LoadOptions& options = budgeted.options;
  return with_transient_charges(options, [&] {
    if (file.scene) charge_load(options, scene_memory_bytes(*file.scene), file.path + ": a copy of the scene");
    SceneDesc scene = file.gltf ? gltf_scene(*file.gltf, options) : *file.scene;
    finish_scene(scene, file.path, options, file.files_read);
    return scene;
  });
}

}  // namespace radiant
