// glTF images, textures (with samplers) and metallic-roughness materials to SceneDesc.
#pragma once

#include "gltf/gltf_context.h"

namespace radiant {

// Appends every glTF texture and material, keeping glTF indices (offset by what the scene
// already held; for glTF files that is zero), and the images the textures show
// (docs/gltf-obj.md, "Texture extensions").
void convert_textures(GltfContext& context);
void convert_materials(GltfContext& context);

// Reading material extensions (tinygltf leaves them as JSON values), shared by their converters.
// `object[key]` when it is a number, else `fallback`.
double number(const tinygltf::Value& object, const char* key, double fallback);
// The extension `name` of `extensions`, or null.
const tinygltf::Value* extension(const tinygltf::ExtensionMap& extensions, const char* name);
// The textureInfo `key` inside a material extension (none when absent), its index checked.
TextureRef extension_texture(const GltfContext& context, const tinygltf::Value& extension_value, const char* key,
                             const std::string& extension_where);
// The RGB factor `key` inside a material extension: three non-negative numbers.
color3 extension_color(const GltfContext& context, const tinygltf::Value& extension_value, const char* key,
                       color3 fallback, const std::string& extension_where);

// The SceneDesc material for glTF material `index` (-1 = the shared glTF default material).
int scene_material(GltfContext& context, int index, const std::string& where);

}  // namespace radiant
