#include "gltf/gltf_materials.h"

#include <cmath>
#include <filesystem>
#include <map>

#include "file_access.h"
#include "gltf/gltf_material_values.h"
#include "gltf/gltf_specular_glossiness.h"
#include "texture_file.h"

namespace radiant {

// ---------------------------------------------------------------- images and textures

// A glTF image as an ImageDesc: as stb_image decoded it, or, for a WebP file beside the glTF
// (EXT_texture_webp), through OpenImageIO.
static ImageDesc convert_image(const GltfContext& context, size_t i) {
  const tinygltf::Image& source = context.model.images[i];
  std::string where = element("images", i);
  if (source.mimeType == "image/webp" && source.image.empty()) {
    if (source.uri.empty() || source.uri.rfind("data:", 0) == 0)
      context.fail(where, "a WebP image inside the file (bufferView or data URI) is not supported; a .webp file beside "
                          "it is");
    std::filesystem::path path = resolve_inside(std::filesystem::absolute(context.file).parent_path(), source.uri,
                                                context.options.allow_external_files, context.file + ": " + where);
    ImageDesc image = read_texture_file(path, context.file + ": " + where, source.uri, context.options);
    image.name = source.name.empty() ? source.uri : source.name;
    return image;
  }
  if (source.mimeType == "image/ktx2" && source.image.empty())
    context.fail(where, "KTX2 images (KHR_texture_basisu) are not supported");
  ImageDesc image;
  image.name = source.name.empty() ? (source.uri.rfind("data:", 0) == 0 ? where : source.uri) : source.name;
  image.width = source.width;
  image.height = source.height;
  image.channels = source.component;
  size_t texels = size_t(std::max(0, source.width)) * size_t(std::max(0, source.height)) *
                  size_t(std::max(0, source.component));
  size_t bytes_per_channel = source.bits == 16 ? 2 : 1;
  if (texels == 0 || source.image.size() != texels * bytes_per_channel)
    context.fail(where, "the image could not be decoded");
  image.texels8.resize(texels);
  // 16-bit PNGs keep their high byte: textures are 8-bit in radiant.
  for (size_t t = 0; t < texels; ++t)
    image.texels8[t] = bytes_per_channel == 2 ? source.image[t * 2 + 1] : source.image[t];
  return image;
}

// The glTF image a texture shows: EXT_texture_webp's source, else the texture's own `source`,
// which is the PNG/JPEG fallback of the image extensions radiant lacks (KHR_texture_basisu's
// KTX2: Debian has no decoder).
static int chosen_image(const GltfContext& context, const tinygltf::Texture& source, const std::string& where) {
  const auto& images = context.model.images;
  auto webp = source.extensions.find("EXT_texture_webp");
  if (webp != source.extensions.end() && webp->second.IsObject() && webp->second.Has("source"))
    return index_value(context, webp->second.Get("source"), images.size(),
                       where + ".extensions.EXT_texture_webp.source", "image");
  if (source.source >= 0) {
    check_index(context, source.source, images.size(), where + ".source", "image");
    return source.source;
  }
  for (const auto& [name, value] : source.extensions)
    if (value.IsObject() && value.Has("source"))
      context.fail(where + ".extensions." + name + ".source",
                   name + " images are not supported and the texture has no PNG or JPEG fallback source");
  context.fail(where, "texture has no image source");
}

static TextureWrap wrap_mode(int mode) {
  switch (mode) {
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return TextureWrap::clamp_to_edge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return TextureWrap::mirrored_repeat;
    default: return TextureWrap::repeat;
  }
}

void convert_textures(GltfContext& context) {
  const auto& model = context.model;
  std::map<int, int> scene_image_of;  // glTF image -> SceneDesc image; only the images shown are kept
  for (size_t i = 0; i < model.textures.size(); ++i) {
    const tinygltf::Texture& source = model.textures[i];
    std::string where = element("textures", i);
    TextureDesc texture;
    int image = chosen_image(context, source, where);
    auto [found, inserted] = scene_image_of.try_emplace(image, int(context.scene.images.size()));
    if (inserted) context.scene.images.push_back(convert_image(context, size_t(image)));
    texture.image = found->second;
    if (source.sampler >= 0) {
      check_index(context, source.sampler, model.samplers.size(), where + ".sampler", "sampler");
      const tinygltf::Sampler& sampler = model.samplers[source.sampler];
      texture.wrap_s = wrap_mode(sampler.wrapS);
      texture.wrap_t = wrap_mode(sampler.wrapT);
      if (sampler.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST) texture.filter = TextureFilter::nearest;
    }
    context.scene.textures.push_back(texture);
  }
}

// ---------------------------------------------------------------- materials

// KHR_materials_specular: the strength and tint of a dielectric's Fresnel layer.
static void convert_specular(const GltfContext& context, const tinygltf::Value& specular, const std::string& where,
                             MaterialDesc& material) {
  std::string specular_where = where + ".extensions.KHR_materials_specular";
  material.specular = non_negative_float(context, number(specular, "specularFactor", 1), specular_where + ".specularFactor");
  material.specular_strength_texture = extension_texture(context, specular, "specularTexture", specular_where);
  material.specular_color = extension_color(context, specular, "specularColorFactor", {1, 1, 1}, specular_where);
  material.specular_color_texture = extension_texture(context, specular, "specularColorTexture", specular_where);
}

// KHR_materials_clearcoat: a clear GGX layer with its own strength and roughness.
static void convert_clearcoat(const GltfContext& context, const tinygltf::Value& clearcoat, const std::string& where,
                              MaterialDesc& material) {
  std::string clearcoat_where = where + ".extensions.KHR_materials_clearcoat";
  material.clearcoat =
      non_negative_float(context, number(clearcoat, "clearcoatFactor", 0), clearcoat_where + ".clearcoatFactor");
  material.clearcoat_texture = extension_texture(context, clearcoat, "clearcoatTexture", clearcoat_where);
  material.clearcoat_roughness = non_negative_float(context, number(clearcoat, "clearcoatRoughnessFactor", 0),
                                                    clearcoat_where + ".clearcoatRoughnessFactor");
  material.clearcoat_roughness_texture =
      extension_texture(context, clearcoat, "clearcoatRoughnessTexture", clearcoat_where);
  material.clearcoat_normal_texture = extension_texture(context, clearcoat, "clearcoatNormalTexture", clearcoat_where);
  if (material.clearcoat_normal_texture.valid()) {
    double scale = number(clearcoat.Get("clearcoatNormalTexture"), "scale", 1);
    if (!(std::abs(scale) <= 1e6))
      context.fail(clearcoat_where + ".clearcoatNormalTexture.scale", number_text(scale) + " is not a usable scale");
    material.clearcoat_normal_scale = float(scale);
  }
}

// KHR_materials_sheen: the colour and roughness of a Charlie sheen.
static void convert_sheen(const GltfContext& context, const tinygltf::Value& sheen, const std::string& where,
                          MaterialDesc& material) {
  std::string sheen_where = where + ".extensions.KHR_materials_sheen";
  material.sheen_color = extension_color(context, sheen, "sheenColorFactor", {0, 0, 0}, sheen_where);
  material.sheen_color_texture = extension_texture(context, sheen, "sheenColorTexture", sheen_where);
  material.sheen_roughness =
      non_negative_float(context, number(sheen, "sheenRoughnessFactor", 0), sheen_where + ".sheenRoughnessFactor");
  material.sheen_roughness_texture = extension_texture(context, sheen, "sheenRoughnessTexture", sheen_where);
}

// KHR_materials_diffuse_transmission: the share of the diffuse base sent through, and its tint.
static void convert_diffuse_transmission(const GltfContext& context, const tinygltf::Value& extension_value,
                                         const std::string& where, MaterialDesc& material) {
  std::string at = where + ".extensions.KHR_materials_diffuse_transmission";
  material.diffuse_transmission = non_negative_float(context, number(extension_value, "diffuseTransmissionFactor", 0),
                                                     at + ".diffuseTransmissionFactor");
  material.diffuse_transmission_texture = extension_texture(context, extension_value, "diffuseTransmissionTexture", at);
  material.diffuse_transmission_color =
      extension_color(context, extension_value, "diffuseTransmissionColorFactor", {1, 1, 1}, at);
  material.diffuse_transmission_color_texture =
      extension_texture(context, extension_value, "diffuseTransmissionColorTexture", at);
}

// KHR_materials_volume: the thickness (0 = a thin wall) and the Beer-Lambert attenuation. The
// thickness texture only matters to rasterizers, which cannot measure the path inside.
static void convert_volume(const GltfContext& context, const tinygltf::Value& volume, const std::string& where,
                           MaterialDesc& material) {
  std::string volume_where = where + ".extensions.KHR_materials_volume";
  material.thickness = non_negative_float(context, number(volume, "thicknessFactor", 0), volume_where + ".thicknessFactor");
  if (volume.Has("attenuationDistance")) {
    std::string distance_where = volume_where + ".attenuationDistance";
    double distance = number(volume, "attenuationDistance", 0);
    if (!(distance > 0)) context.fail(distance_where, "must be positive, got " + number_text(distance));
    material.attenuation_distance = non_negative_float(context, distance, distance_where);
  }
  material.attenuation_color = extension_color(context, volume, "attenuationColor", {1, 1, 1}, volume_where);
}

// KHR_materials_iridescence: the strength, index and thickness range of a thin film.
static void convert_iridescence(const GltfContext& context, const tinygltf::Value& iridescence,
                                const std::string& where, MaterialDesc& material) {
  std::string at = where + ".extensions.KHR_materials_iridescence";
  material.iridescence = non_negative_float(context, number(iridescence, "iridescenceFactor", 0), at + ".iridescenceFactor");
  material.iridescence_texture = extension_texture(context, iridescence, "iridescenceTexture", at);
  material.iridescence_ior = non_negative_float(context, number(iridescence, "iridescenceIor", 1.3), at + ".iridescenceIor");
  material.iridescence_thickness_min = non_negative_float(
      context, number(iridescence, "iridescenceThicknessMinimum", 100), at + ".iridescenceThicknessMinimum");
  material.iridescence_thickness_max = non_negative_float(
      context, number(iridescence, "iridescenceThicknessMaximum", 400), at + ".iridescenceThicknessMaximum");
  material.iridescence_thickness_texture = extension_texture(context, iridescence, "iridescenceThicknessTexture", at);
}

// KHR_materials_anisotropy: the strength, rotation and direction texture of anisotropic GGX.
static void convert_anisotropy(const GltfContext& context, const tinygltf::Value& anisotropy,
                               const std::string& where, MaterialDesc& material) {
  std::string at = where + ".extensions.KHR_materials_anisotropy";
  material.anisotropy_strength =
      non_negative_float(context, number(anisotropy, "anisotropyStrength", 0), at + ".anisotropyStrength");
  double rotation = number(anisotropy, "anisotropyRotation", 0);
  if (!(std::abs(rotation) <= 1e6)) context.fail(at + ".anisotropyRotation", number_text(rotation) + " is not an angle");
  material.anisotropy_rotation = float(rotation);
  material.anisotropy_texture = extension_texture(context, anisotropy, "anisotropyTexture", at);
}

static color3 color_of(const std::vector<double>& factor, color3 fallback) {
  if (factor.size() < 3) return fallback;
  return {float(factor[0]), float(factor[1]), float(factor[2])};
}

static MaterialDesc convert_material(GltfContext& context, const tinygltf::Material& source,
                                     const std::string& where) {
  MaterialDesc material;
  material.name = source.name;
  material.model = MaterialModel::metallic_roughness;
  const auto& pbr = source.pbrMetallicRoughness;
  material.base_color = color_of(pbr.baseColorFactor, {1, 1, 1});
  if (pbr.baseColorFactor.size() == 4) material.alpha = float(pbr.baseColorFactor[3]);
  material.metallic = float(pbr.metallicFactor);
  material.roughness = float(pbr.roughnessFactor);
  std::string pbr_where = where + ".pbrMetallicRoughness";
  material.base_color_texture = core_texture(context, pbr.baseColorTexture, pbr_where + ".baseColorTexture");
  material.metallic_roughness_texture =
      core_texture(context, pbr.metallicRoughnessTexture, pbr_where + ".metallicRoughnessTexture");
  material.normal_texture = core_texture(context, source.normalTexture, where + ".normalTexture");
  material.normal_scale = float(source.normalTexture.scale);
  material.emission_texture = core_texture(context, source.emissiveTexture, where + ".emissiveTexture");
  float strength = 1;
  if (const tinygltf::Value* emissive = extension(source.extensions, "KHR_materials_emissive_strength"))
    strength = non_negative_float(context, number(*emissive, "emissiveStrength", 1),
                                  where + ".extensions.KHR_materials_emissive_strength.emissiveStrength");
  color3 emissive_factor = {0, 0, 0};
  if (source.emissiveFactor.size() >= 3)
    for (int c = 0; c < 3; ++c)
      emissive_factor[c] = non_negative_float(context, source.emissiveFactor[size_t(c)], where + ".emissiveFactor");
  material.emission = emissive_factor * strength;
  if (source.alphaMode == "MASK") material.alpha_mode = AlphaMode::mask;
  else if (source.alphaMode == "BLEND") material.alpha_mode = AlphaMode::blend;
  material.alpha_cutoff = float(source.alphaCutoff);
  material.double_sided = source.doubleSided;
  if (const tinygltf::Value* transmission = extension(source.extensions, "KHR_materials_transmission")) {
    material.transmission = float(number(*transmission, "transmissionFactor", 0));
    material.transmission_texture = extension_texture(context, *transmission, "transmissionTexture",
                                                      where + ".extensions.KHR_materials_transmission");
  }
  if (const tinygltf::Value* specular = extension(source.extensions, "KHR_materials_specular"))
    convert_specular(context, *specular, where, material);
  if (const tinygltf::Value* clearcoat = extension(source.extensions, "KHR_materials_clearcoat"))
    convert_clearcoat(context, *clearcoat, where, material);
  if (const tinygltf::Value* sheen = extension(source.extensions, "KHR_materials_sheen"))
    convert_sheen(context, *sheen, where, material);
  if (const tinygltf::Value* diffuse = extension(source.extensions, "KHR_materials_diffuse_transmission"))
    convert_diffuse_transmission(context, *diffuse, where, material);
  if (const tinygltf::Value* volume = extension(source.extensions, "KHR_materials_volume"))
    convert_volume(context, *volume, where, material);
  if (const tinygltf::Value* iridescence = extension(source.extensions, "KHR_materials_iridescence"))
    convert_iridescence(context, *iridescence, where, material);
  if (const tinygltf::Value* anisotropy = extension(source.extensions, "KHR_materials_anisotropy"))
    convert_anisotropy(context, *anisotropy, where, material);
  if (const tinygltf::Value* dispersion = extension(source.extensions, "KHR_materials_dispersion"))
    material.dispersion = non_negative_float(context, number(*dispersion, "dispersion", 0),
                                             where + ".extensions.KHR_materials_dispersion.dispersion");
  if (const tinygltf::Value* ior = extension(source.extensions, "KHR_materials_ior"))
    material.ior = float(number(*ior, "ior", 1.5));
  material.unlit = extension(source.extensions, "KHR_materials_unlit") != nullptr;
  // Preferred to pbrMetallicRoughness, which such files carry for viewers without the extension.
  if (const tinygltf::Value* spec_gloss = extension(source.extensions, specular_glossiness_extension))
    convert_specular_glossiness(context, *spec_gloss, where, material);
  return material;
}

void convert_materials(GltfContext& context) {
  size_t spec_gloss = 0;
  std::string first_spec_gloss;
  for (size_t i = 0; i < context.model.materials.size(); ++i) {
    const tinygltf::Material& source = context.model.materials[i];
    context.scene.materials.push_back(convert_material(context, source, element("materials", i)));
    if (extension(source.extensions, specular_glossiness_extension) && spec_gloss++ == 0)
      first_spec_gloss = element("materials", i) + ".extensions." + specular_glossiness_extension;
  }
  if (spec_gloss > 0)
    context.warn(first_spec_gloss + ": " + std::to_string(spec_gloss) +
                 " specular-glossiness material(s) converted to metallic-roughness with KHR_materials_specular "
                 "(approximate: the Fresnel curve and the diffuse part's weight differ slightly)");
}

int scene_material(GltfContext& context, int index, const std::string& where) {
  if (index >= 0) {
    check_index(context, index, context.model.materials.size(), where, "material");
    return index;
  }
  if (context.default_material < 0) {
    // glTF 2.0 section 3.9.6: white, fully metallic and rough, opaque, single-sided.
    MaterialDesc material;
    material.name = "glTF default";
    material.model = MaterialModel::metallic_roughness;
    material.double_sided = false;
    context.default_material = int(context.scene.materials.size());
    context.scene.materials.push_back(material);
  }
  return context.default_material;
}

}  // namespace radiant
