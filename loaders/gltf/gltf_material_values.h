// Reading material values: tinygltf leaves extensions as JSON values, shared by their converters.
#pragma once

#include <string>

#include "gltf/gltf_context.h"

namespace radiant {

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
// A textureInfo's texture and UV set, with its KHR_texture_transform (`transform`: the
// extension's object, or null), whose texCoord overrides the textureInfo's; `index` < 0 is none.
// The index and the set are checked, naming `where`.
TextureRef texture_ref(const GltfContext& context, int index, double texcoord, const tinygltf::Value* transform,
                       const std::string& where);

// A core textureInfo (tinygltf parsed it into its own struct).
template <class Info>
TextureRef core_texture(const GltfContext& context, const Info& info, const std::string& where) {
  return texture_ref(context, info.index, info.texCoord, extension(info.extensions, "KHR_texture_transform"), where);
}

}  // namespace radiant
