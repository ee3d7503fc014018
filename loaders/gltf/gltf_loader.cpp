#include "gltf/gltf_loader.h"

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "file_access.h"
#include "gltf/gltf_animation.h"
#include "gltf/gltf_context.h"
#include "gltf/gltf_declarations.h"
#include "gltf/gltf_draco.h"
#include "gltf/gltf_files.h"
#include "gltf/gltf_materials.h"
#include "gltf/gltf_variants.h"
#include "gltf/gltf_memory.h"
#include "gltf/gltf_meshes.h"
#include "gltf/gltf_nodes.h"

namespace radiant {

namespace {

const std::vector<std::string> supported_extensions = {
    "KHR_lights_punctual",       "KHR_materials_emissive_strength", "KHR_texture_transform",
    "KHR_materials_transmission", "KHR_materials_ior",              "KHR_materials_unlit",
    "KHR_materials_specular",     "KHR_materials_clearcoat",        "KHR_materials_sheen",
    "KHR_materials_volume",       "KHR_materials_variants",         "KHR_materials_iridescence",
    "KHR_materials_anisotropy",   "KHR_mesh_quantization",          "KHR_draco_mesh_compression",
    "EXT_texture_webp",           "KHR_materials_dispersion"};

bool is_supported(const std::string& name) {
  return std::find(supported_extensions.begin(), supported_extensions.end(), name) != supported_extensions.end();
}

// The whole file, refused by its size before reading when tinygltf could not take it.
std::string read_gltf_file(const std::string& path, const LoadOptions& options) {
  if (check_input_file(path, path, options) > 0xFFFFFFFFull) throw LoadError(path + ": files over 4 GB are not supported");
  return read_input_file(path, path, options);
}

// Refuses what must be refused before tinygltf allocates anything, and charges the buffers it
// will allocate: each declared length, and once more for a data URI's decoded copy.
void check_declarations(const GltfDeclarations& declared, const std::string& path, const LoadOptions& options) {
  for (const std::string& name : declared.extensions_required)
    if (!is_supported(name))
      throw LoadError(path + ": extensionsRequired: unsupported extension " + name);
  for (size_t i = 0; i < declared.buffer_byte_lengths.size(); ++i) {
    uint64_t length = declared.buffer_byte_lengths[i];
    bool data_uri = i < declared.buffer_uris.size() && declared.buffer_uris[i] == data_uri_marker;
    charge_load(options, data_uri ? saturating_multiply(length, 2) : length,
                path + ": " + element("buffers", i) + ".byteLength");
  }
}

tinygltf::Model parse(const std::string& path, const std::string& bytes, const LoadOptions& options,
                      SceneDesc& scene) {
  bool binary = bytes.compare(0, 4, "glTF") == 0;
  std::string json_chunk;
  if (binary) {
    json_chunk = glb_json_chunk(bytes, path);
    charge_load(options, json_chunk.size(), path + ": the JSON chunk");
  }
  const std::string& json = binary ? json_chunk : bytes;
  GltfJsonCounts counts = count_gltf_json(json, path);
  charge_load(options, gltf_model_bytes(counts, json.size()),
              path + ": the JSON document (" + std::to_string(counts.values) + " values)");
  GltfDeclarations declared = read_gltf_declarations(json, path);
  check_declarations(declared, path, options);
  GltfFileAccess access;
  access.base_dir = std::filesystem::absolute(path).parent_path();
  access.file = path;
  access.options = &options;
  access.declarations = &declared;
  tinygltf::TinyGLTF gltf;
  install_file_access(gltf, access);
  tinygltf::Model model;
  std::string error, warning;
  // Draco files are rewritten through a second JSON tree first, charged like tinygltf's, with
  // the copy of the file it makes.
  if (json.find("KHR_draco_mesh_compression") != std::string::npos)
    charge_load(options, saturating_add(gltf_model_bytes(counts, json.size()), bytes.size()),
                path + ": the JSON document, rewritten for Draco");
  std::string rewritten;
  const std::string& document = with_draco_index_views(bytes, binary, rewritten) ? rewritten : bytes;
  const auto* data = reinterpret_cast<const unsigned char*>(document.data());
  bool ok = false;
  try {
    ok = binary ? gltf.LoadBinaryFromMemory(&model, &error, &warning, data, unsigned(document.size()), "")
                : gltf.LoadASCIIFromString(&model, &error, &warning, document.data(), unsigned(document.size()), "");
  } catch (const std::out_of_range& e) {
    // tinygltf 2.7 follows some indices with an unchecked at(): a primitive's material in a file
    // without materials escapes as std::out_of_range (found by the glTF fuzzer).
    throw LoadError(path + ": invalid glTF: an index refers to an element the file does not have (" +
                    one_line(e.what()) + ")");
  }
  if (!access.error.empty()) throw LoadError(access.error);
  if (!ok) throw LoadError(path + ": " + (error.empty() ? "invalid glTF" : one_line(error)));
  if (!warning.empty()) scene.warnings.push_back(path + ": " + one_line(warning));
  decode_buffer_view_images(model, access);
  return model;
}

}  // namespace

SceneDesc load_gltf(const std::string& path, const LoadOptions& given) {
  BudgetedLoadOptions budgeted(given);
  const LoadOptions& options = budgeted.options;
  std::string bytes = read_gltf_file(path, options);
  SceneDesc scene;
  scene.name = std::filesystem::path(path).stem().string();
  tinygltf::Model model = parse(path, bytes, options, scene);
  GltfContext context{model, path, options, scene, {}, {}, -1};
  context.variant = selected_variant(context);
  for (const std::string& name : model.extensionsUsed)
    if (!is_supported(name)) context.warn("extension " + name + " is not supported and is ignored");
  convert_textures(context);
  convert_materials(context);
  if (options.animation_time) {
    int animation = find_animation(context, options.animation);
    if (animation < 0) context.warn("--time: the file has no animations; its static state is shown");
    else apply_animation(model, context, animation, *options.animation_time);
  }
  decode_draco_primitives(model, context);
  convert_meshes(context);
  convert_nodes(context);
  if (scene.degenerate_triangles_dropped > 0)
    context.warn(std::to_string(scene.degenerate_triangles_dropped) + " degenerate triangles dropped");
  return scene;
}

}  // namespace radiant
