#include "gltf/gltf_loader.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "gltf/gltf_context.h"
#include "gltf/gltf_declarations.h"
#include "gltf/gltf_files.h"
#include "gltf/gltf_materials.h"
#include "gltf/gltf_meshes.h"
#include "gltf/gltf_nodes.h"

namespace radiant {

namespace {

const std::vector<std::string> supported_extensions = {
    "KHR_lights_punctual",       "KHR_materials_emissive_strength", "KHR_texture_transform",
    "KHR_materials_transmission", "KHR_materials_ior",              "KHR_materials_unlit",
    "KHR_mesh_quantization"};

bool is_supported(const std::string& name) {
  return std::find(supported_extensions.begin(), supported_extensions.end(), name) != supported_extensions.end();
}

std::string read_file(const std::string& path, const LoadOptions& options) {
  std::error_code ec;
  uint64_t size = std::filesystem::file_size(path, ec);
  if (ec) throw LoadError(path + ": cannot open (" + ec.message() + ")");
  if (size > options.max_memory_bytes)
    throw LoadError(path + ": the file (" + std::to_string(size) + " bytes) exceeds the memory limit of " +
                    std::to_string(options.max_memory_bytes) + " bytes");
  std::ifstream in(path, std::ios::binary);
  std::string bytes(size, '\0');
  if (!in.read(bytes.data(), std::streamsize(size))) throw LoadError(path + ": read failed");
  return bytes;
}

// Refuses what must be refused before tinygltf allocates anything.
void check_declarations(const GltfDeclarations& declared, const std::string& path, const LoadOptions& options) {
  for (const std::string& name : declared.extensions_required)
    if (!is_supported(name))
      throw LoadError(path + ": extensionsRequired: unsupported extension " + name);
  uint64_t total = 0;
  for (size_t i = 0; i < declared.buffer_byte_lengths.size(); ++i) {
    total += declared.buffer_byte_lengths[i];
    if (total > options.max_memory_bytes)
      throw LoadError(path + ": " + element("buffers", i) + ".byteLength: " +
                      std::to_string(declared.buffer_byte_lengths[i]) + " bytes (" + std::to_string(total) +
                      " in all) exceed the memory limit of " + std::to_string(options.max_memory_bytes) + " bytes");
  }
}

tinygltf::Model parse(const std::string& path, const std::string& bytes, const LoadOptions& options,
                      SceneDesc& scene, uint64_t& bytes_charged) {
  bool binary = bytes.compare(0, 4, "glTF") == 0;
  std::string json = binary ? glb_json_chunk(bytes, path) : bytes;
  GltfDeclarations declared = read_gltf_declarations(json, path);
  check_declarations(declared, path, options);
  GltfFileAccess access;
  access.base_dir = std::filesystem::absolute(path).parent_path();
  access.file = path;
  access.options = &options;
  access.declarations = &declared;
  for (uint64_t length : declared.buffer_byte_lengths) access.bytes_charged += length;
  tinygltf::TinyGLTF gltf;
  install_file_access(gltf, access);
  tinygltf::Model model;
  std::string error, warning;
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  bool ok = binary ? gltf.LoadBinaryFromMemory(&model, &error, &warning, data, unsigned(bytes.size()), "")
                   : gltf.LoadASCIIFromString(&model, &error, &warning, bytes.data(), unsigned(bytes.size()), "");
  if (!access.error.empty()) throw LoadError(access.error);
  if (!ok) throw LoadError(path + ": " + (error.empty() ? "invalid glTF" : one_line(error)));
  if (!warning.empty()) scene.warnings.push_back(path + ": " + one_line(warning));
  decode_buffer_view_images(model, access);
  bytes_charged = bytes.size() + access.bytes_charged;
  return model;
}

}  // namespace

SceneDesc load_gltf(const std::string& path, const LoadOptions& given) {
  LoadOptions options = given;
  if (options.max_memory_bytes == 0) options.max_memory_bytes = default_max_memory();  // called directly
  std::string bytes = read_file(path, options);
  if (bytes.size() > 0xFFFFFFFFull) throw LoadError(path + ": files over 4 GB are not supported");
  SceneDesc scene;
  scene.name = std::filesystem::path(path).stem().string();
  uint64_t bytes_charged = 0;
  tinygltf::Model model = parse(path, bytes, options, scene, bytes_charged);
  GltfContext context{model, path, options, scene, {}, {}, -1, bytes_charged};
  for (const std::string& name : model.extensionsUsed)
    if (!is_supported(name)) context.warn("extension " + name + " is not supported and is ignored");
  convert_images(context);
  convert_textures(context);
  convert_materials(context);
  convert_meshes(context);
  convert_nodes(context);
  if (scene.degenerate_triangles_dropped > 0)
    context.warn(std::to_string(scene.degenerate_triangles_dropped) + " degenerate triangles dropped");
  return scene;
}

}  // namespace radiant
