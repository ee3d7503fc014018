// TEMPORARY: minimal Lambert-only materials until the real implementation lands.
#include <cmath>

#include "materials/surface.h"
#include "sampling/warp.h"

namespace radiant {

vec4 sample_texture(const SceneDesc&, const TextureRef&, const SurfaceAttributes&, bool) { return {1, 1, 1, 1}; }

SurfaceMaterial resolve_material(const SceneDesc&, const MaterialDesc& d, const SurfaceAttributes&) {
  SurfaceMaterial m;
  m.model = d.model;
  m.ka = d.ka, m.kd = d.kd, m.ks = d.ks, m.kr = d.kr, m.kt = d.kt, m.shininess = d.shininess, m.ior = d.ior;
  m.base_color = d.base_color, m.metallic = d.metallic, m.roughness = d.roughness, m.transmission = d.transmission;
  m.emission = d.emission;
  m.unlit = d.unlit;
  if (d.model == MaterialModel::metallic_roughness) phong_from_metallic_roughness(m);
  return m;
}

void phong_from_metallic_roughness(SurfaceMaterial& m) {
  m.kd = m.base_color * (1 - m.metallic);
  m.ks = {0, 0, 0};
  m.kr = m.base_color * m.metallic;
  m.kt = {0, 0, 0};
}

vec3 apply_normal_map(vec3 n, vec4, vec3) { return n; }

color3 eval_bsdf(const SurfaceMaterial& m, vec3 n, vec3 wo, vec3 wi) {
  if (dot(n, wo) <= 0 || dot(n, wi) <= 0) return {};
  return m.kd * (dot(n, wi) * inv_pi);
}
float sample_bsdf_pdf(const SurfaceMaterial& m, vec3 n, vec3 wo, vec3 wi) {
  if (dot(n, wo) <= 0 || dot(n, wi) <= 0 || is_black(m.kd)) return 0;
  return dot(n, wi) * inv_pi;
}
std::optional<BsdfSample> sample_bsdf(const SurfaceMaterial& m, vec3 n, vec3 wo, float, vec2 u) {
  if (dot(n, wo) <= 0) n = -n;
  BsdfSample s;
  s.wi = to_world(n, sample_cosine_hemisphere(u));
  s.pdf = dot(n, s.wi) * inv_pi;
  if (s.pdf <= 0) return std::nullopt;
  s.weight = m.kd;
  return s;
}
bool is_pure_delta(const SurfaceMaterial& m) { return is_black(m.kd); }
color3 bsdf_albedo(const SurfaceMaterial& m) { return m.kd; }

}  // namespace radiant
