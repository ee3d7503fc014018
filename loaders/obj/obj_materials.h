// MTL materials to Phong MaterialDesc, and their texture files loaded through OpenImageIO.
#pragma once

#include <tiny_obj_loader.h>

#include <filesystem>
#include <map>
#include <string>

#include "load_options.h"
#include "scene/scene_desc.h"

namespace radiant {

struct ObjTextureLoader {
  SceneDesc& scene;
  std::filesystem::path base_dir;  // the OBJ's folder: map_* names resolve inside it
  const std::string& file;
  const LoadOptions& options;
  std::map<std::string, int> textures_by_path;  // one TextureDesc per file and wrap mode (-1: missing)
};

// The MaterialDesc for one MTL material (mapping in docs/gltf-obj.md).
MaterialDesc convert_mtl_material(ObjTextureLoader& textures, const tinyobj::material_t& source);

// An 8-bit texture from an image file named in the MTL (a backslash is a folder separator);
// throws LoadError naming `where`. A missing file is a warning and gives -1 (no texture).
int load_obj_texture(ObjTextureLoader& textures, const std::string& name, const tinyobj::texture_option_t& option,
                     const std::string& where);

}  // namespace radiant
