// The path tracer's BSDF: dispatch on the material model.
#include "materials/bsdf_models.h"

namespace radiant {

namespace {

color3 clamp01(color3 c) { return min(max(c, {0, 0, 0}), {1, 1, 1}); }

}  // namespace

color3 eval_bsdf(const SurfaceMaterial& m, vec3 n, vec3 wo, vec3 wi) {
  if (m.unlit) return {0, 0, 0};
  return m.model == MaterialModel::metallic_roughness ? eval_metallic_roughness(m, n, wo, wi)
                                                      : eval_phong(m, n, wo, wi);
}

float sample_bsdf_pdf(const SurfaceMaterial& m, vec3 n, vec3 wo, vec3 wi) {
  if (m.unlit) return 0;
  return m.model == MaterialModel::metallic_roughness ? sample_metallic_roughness_pdf(m, n, wo, wi)
                                                      : sample_phong_pdf(m, n, wo, wi);
}

std::optional<BsdfSample> sample_bsdf(const SurfaceMaterial& m, vec3 n, vec3 wo, float u_lobe, vec2 u) {
  if (m.unlit) return std::nullopt;  // unlit surfaces show their color and scatter nothing
  return m.model == MaterialModel::metallic_roughness ? sample_metallic_roughness(m, n, wo, u_lobe, u)
                                                      : sample_phong(m, n, wo, u_lobe, u);
}

bool is_pure_delta(const SurfaceMaterial& m) {
  if (m.unlit) return true;
  return m.model == MaterialModel::metallic_roughness ? is_metallic_roughness_pure_delta(m)
                                                      : is_phong_pure_delta(m);
}

color3 bsdf_albedo(const SurfaceMaterial& m) {
  return clamp01(m.model == MaterialModel::metallic_roughness ? m.base_color : m.kd);
}

}  // namespace radiant
