#include "load_scene.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "file_access.h"
#include "gltf/gltf_loader.h"
#include "obj/obj_loader.h"
#include "scene/scene_memory.h"
#include "scene/validate.h"
#include "scene_format/scene_format_loader.h"

namespace radiant {

namespace {

// `text` cut to at most `longest` bytes, at a character boundary, saying how long it was.
std::string shortened(const std::string& text, size_t longest) {
  if (text.size() <= longest) return text;
  size_t cut = longest;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // inside a UTF-8 character
  return text.substr(0, cut) + "... (" + std::to_string(text.size()) + " bytes)";
}

}  // namespace

std::string one_line(const std::string& text) {
  std::istringstream lines(text);
  std::string line, out;
  while (std::getline(lines, line) && out.size() <= max_message_excerpt) {
    while (!line.empty() && std::isspace((unsigned char)line.back())) line.pop_back();
    if (!line.empty()) out += (out.empty() ? "" : "; ") + line;
  }
  return shortened(out, max_message_excerpt);
}

std::string escaped(const std::string& whole) {
  std::string out, text = shortened(whole, max_message_excerpt);
  for (char c : text) {
    unsigned char byte = static_cast<unsigned char>(c);
    if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else if (c == '\t') out += "\\t";
    else if (byte < 0x20 || byte == 0x7F) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", byte);
      out += hex;
    } else out += c;
  }
  return out;
}

void charge_load(const LoadOptions& options, uint64_t bytes, const std::string& what) {
  if (!options.budget->try_charge(bytes)) throw LoadError(options.budget->refusal(bytes, what));
}

BudgetedLoadOptions::BudgetedLoadOptions(const LoadOptions& given) : options(given) {
  if (options.budget) return;
  if (given.max_memory_bytes > 0) own_budget.emplace(given.max_memory_bytes, "--max-memory");
  else own_budget.emplace(default_memory_limit(), default_memory_limit_source);
  options.budget = &*own_budget;
}

static std::string lowercase_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

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
