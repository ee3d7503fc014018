// A MaterialDesc evaluated at one surface point: textures and vertex colors applied.
#include "materials/surface.h"

namespace radiant {

namespace {

color3 rgb(vec4 c) { return {c.x, c.y, c.z}; }

float clamp01(float x) { return std::isfinite(x) ? std::clamp(x, 0.0f, 1.0f) : 0.0f; }

// Opacity after the alpha mode: opaque ignores alpha, mask thresholds it, blend keeps it.
float opacity_from_alpha(const MaterialDesc& material, float alpha) {
  switch (material.alpha_mode) {
    case AlphaMode::opaque: return 1;
    case AlphaMode::mask: return alpha >= material.alpha_cutoff ? 1.0f : 0.0f;
    case AlphaMode::blend: return clamp01(alpha);
  }
  return 1;
}

// A normal map's tangent-space normal: texel × 2 − 1, xy scaled, unit ((0, 0, 1) where that fails).
vec3 tangent_space_normal(const SceneDesc& scene, const TextureRef& ref, float scale,
                          const SurfaceAttributes& attributes) {
  vec4 texel = sample_texture(scene, ref, attributes, false);
  vec3 n = {(2 * texel.x - 1) * scale, (2 * texel.y - 1) * scale, 2 * texel.z - 1};
  vec3 unit = normalize(n);
  return is_finite(unit) && length_squared(unit) > 0.5f ? unit : vec3{0, 0, 1};
}

// Shared slots: emission, normal map, alpha mode, unlit.
void resolve_shared(const SceneDesc& scene, const MaterialDesc& material, const SurfaceAttributes& attributes,
                    float alpha, SurfaceMaterial& m) {
  m.emission = material.emission;
  if (material.emission_texture.valid())
    m.emission *= rgb(sample_texture(scene, material.emission_texture, attributes, true));
  if (material.normal_texture.valid()) {
    m.normal_map_sample = tangent_space_normal(scene, material.normal_texture, material.normal_scale, attributes);
    m.has_normal_map = true;
  }
  if (material.bump_texture.valid()) {
    m.height_slope = sample_texture_slope(scene, material.bump_texture, attributes) * material.bump_scale;
    m.has_bump_map = true;
  }
  m.opacity = opacity_from_alpha(material, alpha);
  m.unlit = material.unlit;
}

// KHR_materials_anisotropy: the strength, and the direction (the texture's, or the tangent)
// rotated by the rotation.
void resolve_anisotropy(const SceneDesc& scene, const MaterialDesc& material, const SurfaceAttributes& attributes,
                        SurfaceMaterial& m) {
  vec2 direction = {1, 0};
  float strength = material.anisotropy_strength;
  if (material.anisotropy_texture.valid()) {
    vec4 texel = sample_texture(scene, material.anisotropy_texture, attributes, false);
    vec2 d = {2 * texel.x - 1, 2 * texel.y - 1};
    float length = std::sqrt(d.x * d.x + d.y * d.y);
    if (length > 1e-6f) direction = {d.x / length, d.y / length};
    strength *= texel.z;
  }
  float c = std::cos(material.anisotropy_rotation), s = std::sin(material.anisotropy_rotation);
  m.anisotropy = clamp01(strength);
  m.anisotropy_direction = {c * direction.x - s * direction.y, s * direction.x + c * direction.y};
}

SurfaceMaterial resolve_metallic_roughness(const SceneDesc& scene, const MaterialDesc& material,
                                           const SurfaceAttributes& attributes) {
  SurfaceMaterial m;
  m.model = MaterialModel::metallic_roughness;
  vec4 base = sample_texture(scene, material.base_color_texture, attributes, true);
  m.base_color = material.base_color * rgb(base) * rgb(attributes.vertex_color);
  float alpha = material.alpha * base.w * attributes.vertex_color.w;
  vec4 metallic_roughness = sample_texture(scene, material.metallic_roughness_texture, attributes, false);
  m.metallic = clamp01(material.metallic * metallic_roughness.z);
  m.roughness = clamp01(material.roughness * metallic_roughness.y);
  m.transmission = clamp01(material.transmission * sample_texture(scene, material.transmission_texture,
                                                                   attributes, false).x);
  m.ior = material.ior;
  m.dispersion = material.dispersion;
  m.specular = clamp01(material.specular * sample_texture(scene, material.specular_strength_texture, attributes,
                                                          false).w);
  m.specular_color = max(material.specular_color * rgb(sample_texture(scene, material.specular_color_texture,
                                                                      attributes, true)),
                         {0, 0, 0});
  m.clearcoat = clamp01(material.clearcoat * sample_texture(scene, material.clearcoat_texture, attributes, false).x);
  m.clearcoat_roughness = clamp01(material.clearcoat_roughness *
                                  sample_texture(scene, material.clearcoat_roughness_texture, attributes, false).y);
  m.sheen_color = max(material.sheen_color * rgb(sample_texture(scene, material.sheen_color_texture, attributes, true)),
                      {0, 0, 0});
  m.sheen_roughness = clamp01(material.sheen_roughness *
                              sample_texture(scene, material.sheen_roughness_texture, attributes, false).w);
  m.diffuse_transmission =
      clamp01(material.diffuse_transmission *
              sample_texture(scene, material.diffuse_transmission_texture, attributes, false).w);
  m.diffuse_transmission_color =
      max(material.diffuse_transmission_color *
              rgb(sample_texture(scene, material.diffuse_transmission_color_texture, attributes, true)),
          {0, 0, 0});
  m.iridescence = clamp01(material.iridescence * sample_texture(scene, material.iridescence_texture, attributes,
                                                                false).x);
  m.iridescence_ior = material.iridescence_ior;
  m.iridescence_thickness = material.iridescence_thickness_max;
  if (material.iridescence_thickness_texture.valid()) {
    float t = sample_texture(scene, material.iridescence_thickness_texture, attributes, false).y;
    m.iridescence_thickness = material.iridescence_thickness_min +
                              (material.iridescence_thickness_max - material.iridescence_thickness_min) * t;
  }
  if (material.clearcoat_normal_texture.valid()) {
    m.clearcoat_normal_sample =
        tangent_space_normal(scene, material.clearcoat_normal_texture, material.clearcoat_normal_scale, attributes);
    m.has_clearcoat_normal_map = true;
  }
  resolve_anisotropy(scene, material, attributes, m);
  resolve_shared(scene, material, attributes, alpha, m);
  phong_from_metallic_roughness(m);
  return m;
}

SurfaceMaterial resolve_phong(const SceneDesc& scene, const MaterialDesc& material,
                              const SurfaceAttributes& attributes) {
  SurfaceMaterial m;
  m.model = MaterialModel::phong;
  vec4 diffuse = sample_texture(scene, material.base_color_texture, attributes, true);
  m.kd = material.kd * rgb(diffuse) * rgb(attributes.vertex_color);
  m.ks = material.ks * rgb(sample_texture(scene, material.specular_texture, attributes, false));
  m.ka = material.ka;
  m.kr = material.kr;
  m.kt = material.kt;
  m.shininess = material.shininess;
  m.ior = material.ior;
  float alpha = material.alpha * diffuse.w * attributes.vertex_color.w *
                sample_texture(scene, material.alpha_texture, attributes, false).x;
  resolve_shared(scene, material, attributes, alpha, m);
  return m;
}

}  // namespace

std::vector<TextureSlot> texture_slots(const MaterialDesc& m) {
  return {{&m.base_color_texture, true},         {&m.metallic_roughness_texture, false},
          {&m.normal_texture, false},            {&m.bump_texture, false},
          {&m.transmission_texture, false},      {&m.specular_strength_texture, false},
          {&m.specular_color_texture, true},     {&m.clearcoat_texture, false},
          {&m.clearcoat_roughness_texture, false}, {&m.clearcoat_normal_texture, false},
          {&m.sheen_color_texture, true},
          {&m.sheen_roughness_texture, false},   {&m.anisotropy_texture, false},
          {&m.diffuse_transmission_texture, false}, {&m.diffuse_transmission_color_texture, true},
          {&m.iridescence_texture, false},       {&m.iridescence_thickness_texture, false},
          {&m.specular_texture, false},          {&m.alpha_texture, false},
          {&m.emission_texture, true}};
}

SurfaceMaterial resolve_material(const SceneDesc& scene, const MaterialDesc& material,
                                 const SurfaceAttributes& attributes) {
  if (material.model == MaterialModel::metallic_roughness)
    return resolve_metallic_roughness(scene, material, attributes);
  return resolve_phong(scene, material, attributes);
}

}  // namespace radiant
