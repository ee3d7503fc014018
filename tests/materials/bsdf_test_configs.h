// BSDF configurations and a deterministic random source shared by the materials tests.
#pragma once

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "materials/bsdf.h"

namespace radiant::test {

// Uniform floats in [0, 1) from a fixed-seed Mersenne twister (24 bits: never exactly 1).
struct UniformRandom {
  std::mt19937 engine;
  explicit UniformRandom(unsigned seed) : engine(seed) {}
  float next() { return float(engine() >> 8) * 0x1p-24f; }
  vec2 next2() { return {next(), next()}; }
};

struct BsdfConfig {
  std::string name;
  SurfaceMaterial material;
  bool from_inside = false;  // wo arrives from below the authored normal
};

inline SurfaceMaterial metallic_roughness(color3 base, float metallic, float roughness,
                                          float transmission = 0, float ior = 1.5f) {
  SurfaceMaterial m;
  m.model = MaterialModel::metallic_roughness;
  m.base_color = base;
  m.metallic = metallic;
  m.roughness = roughness;
  m.transmission = transmission;
  m.ior = ior;
  phong_from_metallic_roughness(m);
  return m;
}

// A dielectric with KHR_materials_specular's strength and F0 tint.
inline SurfaceMaterial specular_dielectric(color3 base, float roughness, float specular, color3 specular_color) {
  SurfaceMaterial m = metallic_roughness(base, 0, roughness);
  m.specular = specular;
  m.specular_color = specular_color;
  phong_from_metallic_roughness(m);
  return m;
}

// `base` under a KHR_materials_clearcoat layer.
inline SurfaceMaterial coated(SurfaceMaterial base, float clearcoat, float clearcoat_roughness) {
  base.clearcoat = clearcoat;
  base.clearcoat_roughness = clearcoat_roughness;
  phong_from_metallic_roughness(base);
  return base;
}

// `base` under a KHR_materials_sheen layer.
inline SurfaceMaterial sheened(SurfaceMaterial base, color3 sheen_color, float sheen_roughness) {
  base.sheen_color = sheen_color;
  base.sheen_roughness = sheen_roughness;
  phong_from_metallic_roughness(base);
  return base;
}

// `base` under a KHR_materials_iridescence film of index `film_ior` and `thickness` nanometres.
inline SurfaceMaterial iridescent(SurfaceMaterial base, float iridescence, float film_ior, float thickness) {
  base.iridescence = iridescence;
  base.iridescence_ior = film_ior;
  base.iridescence_thickness = thickness;
  phong_from_metallic_roughness(base);
  return base;
}

// `base` with KHR_materials_anisotropy of `strength` (along the frame's x axis).
inline SurfaceMaterial anisotropic(SurfaceMaterial base, float strength) {
  base.anisotropy = strength;
  phong_from_metallic_roughness(base);
  return base;
}

// `base` with KHR_materials_diffuse_transmission: `share` of its diffuse sent through, tinted `color`.
inline SurfaceMaterial diffuse_transmitting(SurfaceMaterial base, float share, color3 color) {
  base.diffuse_transmission = share;
  base.diffuse_transmission_color = color;
  phong_from_metallic_roughness(base);
  return base;
}

// The exactly Lambertian glTF material: metallic 0, specularFactor 0.
inline SurfaceMaterial gltf_lambert(color3 base) { return specular_dielectric(base, 1, 0, {1, 1, 1}); }

inline SurfaceMaterial phong(color3 kd, color3 ks, float shininess, color3 kr = {}, color3 kt = {},
                             float ior = 1.5f) {
  SurfaceMaterial m;
  m.model = MaterialModel::phong;
  m.kd = kd, m.ks = ks, m.shininess = shininess, m.kr = kr, m.kt = kt, m.ior = ior;
  return m;
}

// Every configuration with only non-delta lobes (the ones a histogram can test).
inline std::vector<BsdfConfig> non_delta_configs() {
  color3 white = {1, 1, 1}, grey = {0.8f, 0.8f, 0.8f};
  return {
      {"lambert (specularFactor 0)", gltf_lambert(grey)},
      {"ggx dielectric roughness 0.2", metallic_roughness(grey, 0, 0.2f)},
      {"ggx dielectric roughness 0.5", metallic_roughness(grey, 0, 0.5f)},
      {"ggx dielectric roughness 0.9", metallic_roughness(grey, 0, 0.9f)},
      // Roughness 1 keeps its Fresnel layer, as the glTF BRDF defines it.
      {"ggx dielectric roughness 1.0", metallic_roughness(grey, 0, 1)},
      {"half-strength tinted specular roughness 0.4", specular_dielectric(grey, 0.4f, 0.5f, {2, 1, 0.25f})},
      {"specular color saturating F0 roughness 0.6", specular_dielectric(grey, 0.6f, 1, {40, 40, 40})},
      {"clearcoat 1 roughness 0.3 over plastic 0.5", coated(metallic_roughness(grey, 0, 0.5f), 1, 0.3f)},
      {"clearcoat 0.5 roughness 0.2 over metal 0.4", coated(metallic_roughness({0.9f, 0.6f, 0.3f}, 1, 0.4f), 0.5f, 0.2f)},
      {"clearcoat 1 roughness 0.6 over lambert", coated(gltf_lambert(grey), 1, 0.6f)},
      {"clearcoat 1 roughness 0.2 over rough glass from outside", coated(metallic_roughness(white, 0, 0.3f, 1), 1, 0.2f)},
      {"clearcoat 1 roughness 0.2 over rough glass from inside", coated(metallic_roughness(white, 0, 0.3f, 1), 1, 0.2f),
       true},
      {"sheen 0.8 roughness 0.5 over lambert", sheened(gltf_lambert(grey), {0.8f, 0.6f, 0.4f}, 0.5f)},
      {"sheen 1 roughness 0.2 over plastic 0.5 under clearcoat 0.6",
       coated(sheened(metallic_roughness(grey, 0, 0.5f), {1, 1, 1}, 0.2f), 0.6f, 0.3f)},
      {"anisotropic metal roughness 0.3 strength 0.8", anisotropic(metallic_roughness({0.9f, 0.6f, 0.3f}, 1, 0.3f), 0.8f)},
      {"anisotropic plastic roughness 0.5 strength 0.5", anisotropic(metallic_roughness(grey, 0, 0.5f), 0.5f)},
      {"anisotropic rough glass 0.2 strength 0.6 from inside", anisotropic(metallic_roughness(white, 0, 0.2f, 1), 0.6f),
       true},
      {"iridescent metal roughness 0.4", iridescent(metallic_roughness({0.9f, 0.6f, 0.3f}, 1, 0.4f), 1, 1.8f, 350)},
      {"half-iridescent plastic roughness 0.3", iridescent(metallic_roughness(grey, 0, 0.3f), 0.5f, 1.3f, 500)},
      {"sheen 0.5 roughness 1 over metal 0.3", sheened(metallic_roughness({0.9f, 0.6f, 0.3f}, 1, 0.3f), {0.5f, 0.5f, 0.5f}, 1)},
      {"ggx metal roughness 0.3", metallic_roughness({0.9f, 0.6f, 0.3f}, 1, 0.3f)},
      {"diffuse transmission 0.6 under plastic roughness 0.5",
       diffuse_transmitting(metallic_roughness(grey, 0, 0.5f), 0.6f, {0.9f, 0.5f, 0.2f})},
      {"diffuse transmission 1 under lambert seen from below", diffuse_transmitting(gltf_lambert(grey), 1, white), true},
      {"diffuse transmission 0.5 under sheen and clearcoat",
       coated(sheened(diffuse_transmitting(metallic_roughness(grey, 0, 0.4f), 0.5f, white), {0.6f, 0.6f, 0.6f}, 0.5f),
              0.5f, 0.3f)},
      {"ggx metal roughness 1.0", metallic_roughness({0.9f, 0.6f, 0.3f}, 1, 1)},
      {"rough transmission 0.3 from outside", metallic_roughness(white, 0, 0.3f, 1, 1.5f)},
      {"rough transmission 0.3 from inside", metallic_roughness(white, 0, 0.3f, 1, 1.5f), true},
      {"half metal half glass roughness 0.5", metallic_roughness(white, 0.5f, 0.5f, 0.5f)},
      // The glass half has ior 1: it passes light straight through (delta), the metal's lobe stays.
      {"half metal half ior-1 glass roughness 0.6 from outside", metallic_roughness(white, 0.5f, 0.6f, 1, 1.0f)},
      {"half metal half ior-1 glass roughness 0.6 from inside", metallic_roughness(white, 0.5f, 0.6f, 1, 1.0f), true},
      {"phong shininess 10", phong({0, 0, 0}, {0.9f, 0.9f, 0.9f}, 10)},
      {"phong shininess 100", phong({0, 0, 0}, {0.9f, 0.9f, 0.9f}, 100)},
      {"phong matte (the Lambert model)", phong({0.7f, 0.5f, 0.3f}, {}, 1)},
      {"phong diffuse and specular", phong({0.5f, 0.4f, 0.3f}, {0.3f, 0.3f, 0.3f}, 20)},
  };
}

// Configurations with delta lobes too, for the energy tests.
inline std::vector<BsdfConfig> delta_configs() {
  color3 white = {1, 1, 1};
  return {
      {"smooth glass from outside", metallic_roughness(white, 0, 0, 1, 1.5f)},
      {"smooth glass from inside", metallic_roughness(white, 0, 0, 1, 1.5f), true},
      {"smooth metal", metallic_roughness(white, 1, 0)},
      {"smooth plastic", metallic_roughness(white, 0, 0)},
      {"smooth clearcoat over smooth metal", coated(metallic_roughness(white, 1, 0), 1, 0)},
      {"smooth clearcoat over rough plastic", coated(metallic_roughness(white, 0, 0.5f), 0.7f, 0)},
      {"rough clearcoat over clear glass (smooth)", coated(metallic_roughness(white, 0, 0, 1), 1, 0.4f)},
      {"sheen over a smooth metal", sheened(metallic_roughness(white, 1, 0), {0.7f, 0.7f, 0.7f}, 0.4f)},
      {"phong mirror and glass", phong({0.2f, 0.2f, 0.2f}, {0.1f, 0.1f, 0.1f}, 30, {0.5f, 0.5f, 0.5f},
                                       {0.5f, 0.5f, 0.5f})},
      {"phong glass from inside", phong({}, {}, 1, {0.1f, 0.1f, 0.1f}, {0.9f, 0.9f, 0.9f}), true},
      {"rough ior-1 glass (straight through) from outside", metallic_roughness(white, 0, 0.6f, 1, 1.0f)},
      {"rough ior-1 glass (straight through) from inside", metallic_roughness(white, 0, 0.6f, 1, 1.0f), true},
  };
}

// Directional albedo: the mean sample weight, absorbed samples counting 0.
inline color3 directional_albedo(const SurfaceMaterial& m, vec3 n, vec3 wo, int samples, unsigned seed) {
  UniformRandom random(seed);
  color3 sum;
  for (int k = 0; k < samples; ++k) {
    float u_lobe = random.next();
    if (auto s = Bsdf(m, n, wo).sample(u_lobe, random.next2())) sum += s->weight;
  }
  return sum / float(samples);
}

// A unit direction at polar cosine `cos_theta` from +z, azimuth `phi`.
inline vec3 spherical_direction(float cos_theta, float phi) {
  float sin_theta = std::sqrt(std::max(0.0f, 1 - cos_theta * cos_theta));
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

// The outgoing direction of a config at polar cosine `cos_theta` (below +z when from inside).
inline vec3 config_wo(const BsdfConfig& config, float cos_theta) {
  vec3 wo = spherical_direction(cos_theta, 0.7f);
  if (config.from_inside) wo.z = -wo.z;
  return wo;
}

}  // namespace radiant::test
