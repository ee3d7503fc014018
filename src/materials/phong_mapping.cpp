// The Whitted mapping of metallic-roughness parameters onto the Phong model (docs/materials.md).
#include "materials/metallic_roughness.h"
#include "materials/surface.h"

namespace radiant {

namespace {

// Blinn-Phong exponent equivalent to a Beckmann/GGX alpha (Walter et al. 2007): 2/alpha^2 - 2.
float shininess_from_roughness(float roughness) {
  float alpha = roughness_to_alpha(roughness);
  if (alpha < 1e-2f) return 10000;  // 2/alpha^2 would exceed the clamp anyway
  return std::clamp(2 / (alpha * alpha) - 2, 1.0f, 10000.0f);
}

}  // namespace

void phong_from_metallic_roughness(SurfaceMaterial& m) {
  float metallic = std::clamp(m.metallic, 0.0f, 1.0f);
  float transmission = std::clamp(m.transmission, 0.0f, 1.0f);
  float smoothness = 1 - std::clamp(m.roughness, 0.0f, 1.0f);
  float f0 = dielectric_f0(m.ior);
  m.kd = m.base_color * ((1 - metallic) * (1 - transmission));
  m.ka = m.kd;
  // Highlight weight: Fresnel at normal incidence; a fully rough dielectric's highlight is dropped.
  color3 dielectric_ks = color3{f0, f0, f0} * dielectric_specular_fade(m.roughness);
  m.ks = lerp(dielectric_ks, m.base_color, metallic);
  m.shininess = shininess_from_roughness(m.roughness);
  // Mirror reflection only as far as the surface is smooth.
  m.kr = lerp(color3{f0, f0, f0}, m.base_color, metallic) * (smoothness * smoothness);
  m.kt = m.base_color * (transmission * (1 - metallic));
}

}  // namespace radiant
