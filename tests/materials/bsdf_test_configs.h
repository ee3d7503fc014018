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
      {"lambert", metallic_roughness(grey, 0, 1)},
      {"ggx dielectric roughness 0.2", metallic_roughness(grey, 0, 0.2f)},
      {"ggx dielectric roughness 0.5", metallic_roughness(grey, 0, 0.5f)},
      // At roughness 1 a dielectric is exactly "lambert" (docs/materials.md); 0.9 keeps its GGX coat.
      {"ggx dielectric roughness 0.9", metallic_roughness(grey, 0, 0.9f)},
      {"ggx metal roughness 0.3", metallic_roughness({0.9f, 0.6f, 0.3f}, 1, 0.3f)},
      {"ggx metal roughness 1.0", metallic_roughness({0.9f, 0.6f, 0.3f}, 1, 1)},
      {"rough transmission 0.3 from outside", metallic_roughness(white, 0, 0.3f, 1, 1.5f)},
      {"rough transmission 0.3 from inside", metallic_roughness(white, 0, 0.3f, 1, 1.5f), true},
      {"half metal half glass roughness 0.5", metallic_roughness(white, 0.5f, 0.5f, 0.5f)},
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
      {"phong mirror and glass", phong({0.2f, 0.2f, 0.2f}, {0.1f, 0.1f, 0.1f}, 30, {0.5f, 0.5f, 0.5f},
                                       {0.5f, 0.5f, 0.5f})},
      {"phong glass from inside", phong({}, {}, 1, {0.1f, 0.1f, 0.1f}, {0.9f, 0.9f, 0.9f}), true},
  };
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
