#include "gltf/gltf_material_values.h"

namespace radiant {

double number(const tinygltf::Value& object, const char* key, double fallback) {
  if (!object.IsObject() || !object.Has(key) || !object.Get(key).IsNumber()) return fallback;
  return object.Get(key).GetNumberAsDouble();
}

const tinygltf::Value* extension(const tinygltf::ExtensionMap& extensions, const char* name) {
  auto it = extensions.find(name);
  return it == extensions.end() ? nullptr : &it->second;
}

namespace {

vec2 pair_of(const tinygltf::Value& object, const char* key, vec2 fallback) {
  if (!object.Has(key)) return fallback;
  const tinygltf::Value& v = object.Get(key);
  if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber()) return fallback;
  return {float(v.Get(0).GetNumberAsDouble()), float(v.Get(1).GetNumberAsDouble())};
}

// The UV set a texture reads: TEXCOORD_0 or _1, checked while still a double (extensions give
// any JSON number, and converting one outside int's range is undefined behaviour).
int texcoord_set(const GltfContext& context, double texcoord, const std::string& where) {
  if (texcoord != 0 && texcoord != 1)
    context.fail(where, "TEXCOORD_" + number_text(texcoord) + " is not supported (0 or 1)");
  return int(texcoord);
}

}  // namespace

TextureRef texture_ref(const GltfContext& context, int index, double texcoord, const tinygltf::Value* transform,
                       const std::string& where) {
  TextureRef ref;
  if (index < 0) return ref;
  check_index(context, index, context.model.textures.size(), where + ".index", "texture");
  ref.texture = index;
  std::string texcoord_where = where + ".texCoord";
  if (transform) {
    ref.offset = pair_of(*transform, "offset", ref.offset);
    ref.scale = pair_of(*transform, "scale", ref.scale);
    ref.rotation = float(number(*transform, "rotation", 0));
    if (transform->Has("texCoord")) {
      texcoord = number(*transform, "texCoord", texcoord);
      texcoord_where = where + ".extensions.KHR_texture_transform.texCoord";
    }
  }
  ref.texcoord = texcoord_set(context, texcoord, texcoord_where);
  return ref;
}

TextureRef extension_texture(const GltfContext& context, const tinygltf::Value& extension_value, const char* key,
                             const std::string& extension_where) {
  if (!extension_value.Has(key)) return {};
  const tinygltf::Value& info = extension_value.Get(key);
  std::string info_where = extension_where + "." + key;
  int index = info.Has("index") ? index_value(context, info.Get("index"), context.model.textures.size(),
                                              info_where + ".index", "texture")
                                : -1;
  // An extension's textureInfo is plain JSON: its own extensions (KHR_texture_transform) too.
  const tinygltf::Value* transform = nullptr;
  if (info.Has("extensions") && info.Get("extensions").Has("KHR_texture_transform"))
    transform = &info.Get("extensions").Get("KHR_texture_transform");
  if (transform && !transform->IsObject()) transform = nullptr;
  return texture_ref(context, index, number(info, "texCoord", 0), transform, info_where);
}

color3 extension_color(const GltfContext& context, const tinygltf::Value& extension_value, const char* key,
                       color3 fallback, const std::string& extension_where) {
  if (!extension_value.Has(key)) return fallback;
  const tinygltf::Value& v = extension_value.Get(key);
  std::string where = extension_where + "." + key;
  if (!v.IsArray() || v.ArrayLen() != 3) context.fail(where, "must be an array of 3 numbers");
  color3 c;
  for (int i = 0; i < 3; ++i) {
    if (!v.Get(i).IsNumber()) context.fail(where, "must be an array of 3 numbers");
    c[i] = non_negative_float(context, v.Get(i).GetNumberAsDouble(), where);
  }
  return c;
}

}  // namespace radiant
