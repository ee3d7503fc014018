#include "gltf/gltf_specular_glossiness.h"

#include <cmath>

#include "gltf/gltf_material_values.h"
#include "materials/metallic_roughness.h"

namespace radiant {

namespace {

// The coating's index: with it, specularColorFactor = specular / F0(1.5) gives F0 = specular
// exactly, and the Fresnel curve still rises to 1 at grazing as a dielectric's does.
constexpr float coating_ior = 1.5f;

// A factor in [0, 1] (glossinessFactor, the diffuseFactor's components).
float unit_factor(const GltfContext& context, double value, const std::string& where) {
  if (!(value >= 0 && value <= 1)) context.fail(where, "must be between 0 and 1, got " + number_text(value));
  return float(value);
}

// diffuseFactor: RGBA, four numbers in [0, 1].
vec4 diffuse_factor(const GltfContext& context, const tinygltf::Value& spec_gloss, const std::string& at) {
  if (!spec_gloss.Has("diffuseFactor")) return {1, 1, 1, 1};
  const tinygltf::Value& v = spec_gloss.Get("diffuseFactor");
  std::string where = at + ".diffuseFactor";
  if (!v.IsArray() || v.ArrayLen() != 4) context.fail(where, "must be an array of 4 numbers");
  float c[4];
  for (int i = 0; i < 4; ++i) {
    if (!v.Get(i).IsNumber()) context.fail(where, "must be an array of 4 numbers");
    c[i] = unit_factor(context, v.Get(i).GetNumberAsDouble(), where);
  }
  return {c[0], c[1], c[2], c[3]};
}

// A texture of one channel, 1 - glossiness × the alpha of texture `texture`'s image, read as
// roughness on the same sampler (made once per texture and factor); -1 when the image has no
// alpha, whose glossiness is then the factor alone.
int roughness_from_glossiness(GltfContext& context, int texture, float glossiness, const std::string& where) {
  auto key = std::make_pair(texture, glossiness);
  if (auto found = context.roughness_from_glossiness.find(key); found != context.roughness_from_glossiness.end())
    return found->second;
  SceneDesc& scene = context.scene;
  const TextureDesc source = scene.textures.at(size_t(texture));
  const ImageDesc& image = scene.images.at(size_t(source.image));
  size_t texels = size_t(image.width) * size_t(image.height), channels = size_t(image.channels);
  if ((channels != 2 && channels != 4) || image.texels8.size() != texels * channels)
    return context.roughness_from_glossiness[key] = -1;
  context.charge(texels, where + ": its roughness, made from the glossiness in alpha");
  ImageDesc roughness;
  roughness.name = image.name + " (roughness from glossiness)";
  roughness.width = image.width, roughness.height = image.height, roughness.channels = 1;
  roughness.texels8.resize(texels);
  for (size_t t = 0; t < texels; ++t)
    roughness.texels8[t] = uint8_t(255 - std::lround(glossiness * float(image.texels8[t * channels + channels - 1])));
  TextureDesc derived = source;
  derived.image = int(scene.images.size());
  scene.images.push_back(std::move(roughness));
  scene.textures.push_back(derived);
  return context.roughness_from_glossiness[key] = int(scene.textures.size() - 1);
}

}  // namespace

void convert_specular_glossiness(GltfContext& context, const tinygltf::Value& spec_gloss, const std::string& where,
                                 MaterialDesc& material) {
  std::string at = where + ".extensions.KHR_materials_pbrSpecularGlossiness";
  vec4 diffuse = diffuse_factor(context, spec_gloss, at);
  material.base_color = {diffuse.x, diffuse.y, diffuse.z};
  material.alpha = diffuse.w;
  material.base_color_texture = extension_texture(context, spec_gloss, "diffuseTexture", at);
  material.metallic = 0;
  material.ior = coating_ior;
  material.specular = 1;
  material.specular_strength_texture = {};
  color3 specular = extension_color(context, spec_gloss, "specularFactor", {1, 1, 1}, at);
  material.specular_color = specular / dielectric_f0(coating_ior);
  // The texture's RGB is the specular colour (sRGB), its alpha the glossiness (linear).
  TextureRef texture = extension_texture(context, spec_gloss, "specularGlossinessTexture", at);
  material.specular_color_texture = texture;
  float glossiness = unit_factor(context, number(spec_gloss, "glossinessFactor", 1), at + ".glossinessFactor");
  material.roughness = 1 - glossiness;
  material.metallic_roughness_texture = {};
  if (texture.valid()) {
    int roughness = roughness_from_glossiness(context, texture.texture, glossiness, at + ".specularGlossinessTexture");
    if (roughness >= 0) {
      material.metallic_roughness_texture = texture;
      material.metallic_roughness_texture.texture = roughness;
      material.roughness = 1;
    }
  }
}

}  // namespace radiant
