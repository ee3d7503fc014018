// The Whitted mapping of metallic-roughness parameters onto the Phong model (docs/materials.md).
#include "materials/metallic_roughness.h"
#include "materials/sheen.h"
#include "materials/surface.h"
#include "materials/thin_film.h"

namespace radiant {

namespace {

// Blinn-Phong exponent equivalent to a Beckmann/GGX alpha (Walter et al. 2007): 2/alpha^2 - 2.
float shininess_from_roughness(float roughness) {
  float alpha = roughness_to_alpha(roughness);
  if (alpha < 1e-2f) return 10000;  // 2/alpha^2 would exceed the clamp anyway
  return std::clamp(2 / (alpha * alpha) - 2, 1.0f, 10000.0f);
}

// KHR_materials_sheen: Whitted has no sheen lobe; the sheen colour's diffuse-like share (its
// albedo at normal incidence) joins kd, taken from the base.
void add_sheen_to_phong(SurfaceMaterial& m) {
  float strength = max_component(min(max(m.sheen_color, {0, 0, 0}), {1, 1, 1}));
  if (!(strength > 0)) return;
  float e = sheen_albedo(1, m.sheen_roughness);
  m.kd = m.kd * (1 - strength * e) + min(max(m.sheen_color, {0, 0, 0}), {1, 1, 1}) * e;
  m.ka = m.kd;
  m.ks *= 1 - strength * e;
}

// KHR_materials_clearcoat: the coat's normal-incidence reflectance joins the highlight and, as far
// as the coat is smooth, the mirror; what it reflects the layers below do not get.
void add_clearcoat_to_phong(SurfaceMaterial& m) {
  float coat = std::clamp(m.clearcoat, 0.0f, 1.0f) * dielectric_f0(1.5f);
  if (!(coat > 0)) return;
  float coat_smoothness = 1 - std::clamp(m.clearcoat_roughness, 0.0f, 1.0f);
  color3 below = color3{1, 1, 1} * (1 - coat);
  m.kd *= below;
  m.ka = m.kd;
  m.kt *= below;
  m.ks = m.ks * below + color3{coat, coat, coat};
  m.kr = m.kr * below + color3{coat, coat, coat} * (coat_smoothness * coat_smoothness);
}

}  // namespace

void phong_from_metallic_roughness(SurfaceMaterial& m) {
  float metallic = std::clamp(m.metallic, 0.0f, 1.0f);
  float transmission = std::clamp(m.transmission, 0.0f, 1.0f);
  float smoothness = 1 - std::clamp(m.roughness, 0.0f, 1.0f);
  color3 plastic_f0 = tinted_dielectric_f0(m.ior, m.specular_color);
  color3 metal_f0 = m.base_color;
  // KHR_materials_iridescence: a share of each F0 is the thin film's reflectance at normal incidence.
  float iridescence = std::clamp(m.iridescence, 0.0f, 1.0f);
  if (iridescence > 0) {
    ThinFilm film{m.iridescence_ior, std::max(m.iridescence_thickness, 0.0f)};
    float outside = m.clearcoat > 0 ? 1.5f : 1.0f;
    plastic_f0 = lerp(plastic_f0, thin_film_fresnel(1, outside, film, plastic_f0), iridescence);
    metal_f0 = lerp(metal_f0, thin_film_fresnel(1, outside, film, metal_f0), iridescence);
  }
  color3 f0 = plastic_f0 * std::clamp(m.specular, 0.0f, 1.0f);
  // KHR_materials_diffuse_transmission's share leaves on the other side: Phong has no lobe there.
  float diffuse_transmission = std::clamp(m.diffuse_transmission, 0.0f, 1.0f);
  m.kd = m.base_color * ((1 - metallic) * (1 - transmission) * (1 - diffuse_transmission));
  m.ka = m.kd;
  // Highlight weight: Fresnel at normal incidence (KHR_materials_specular's strength and tint).
  m.ks = lerp(f0, metal_f0, metallic);
  m.shininess = shininess_from_roughness(m.roughness);
  // Mirror reflection only as far as the surface is smooth.
  m.kr = lerp(f0, metal_f0, metallic) * (smoothness * smoothness);
  m.kt = m.base_color * (transmission * (1 - metallic));
  add_sheen_to_phong(m);
  add_clearcoat_to_phong(m);
}

}  // namespace radiant
