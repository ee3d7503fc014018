// The Phong model as a path-tracing BSDF: normalized diffuse, the modified Phong lobe
// ks (n+2)/(2 pi) cos^n (Lafortune & Willems 1994), a delta mirror (kr) and a delta
// transmission (kt), scaled per channel so that kd + ks + kr + kt <= 1 (docs/materials.md).
#include "materials/bsdf_models.h"
#include "materials/lobe_sampling.h"
#include "materials/shading_frame.h"

namespace radiant {

namespace {

float phong_lobe(const PhongLobes& l, vec3 wi) { return phong_lobe_power(dot(wi, reflect_local(l.wo)), l.exponent); }

// Refraction through the smooth interface; total internal reflection turns it into a mirror.
BsdfSample sample_delta_transmission(const PhongLobes& l) {
  vec3 wi;
  if (l.eta == 1) wi = -l.wo;  // index-matched: straight through, no bending
  else if (!refract(l.wo, {0, 0, 1}, l.eta, wi)) wi = reflect_local(l.wo);
  return delta_sample(l, wi, l.kt, l.p_transmission);
}

}  // namespace

float phong_lobe_power(float cos_alpha, float exponent) {
  return cos_alpha > 0 ? std::pow(std::min(cos_alpha, 1.0f), exponent) : 0;
}

vec3 sample_phong_lobe(vec3 wo, float exponent, vec2 u) {
  float cos_alpha = std::pow(u.x, 1 / (exponent + 1));
  float sin_alpha = std::sqrt(std::max(0.0f, 1 - cos_alpha * cos_alpha));
  float phi = 2 * pi * u.y;
  vec3 axis = reflect_local(wo), t, b;
  orthonormal_basis(axis, t, b);
  return normalize(t * (sin_alpha * std::cos(phi)) + b * (sin_alpha * std::sin(phi)) + axis * cos_alpha);
}

PhongWeights make_phong_weights(const SurfaceMaterial& m) {
  PhongWeights w;
  w.ior = std::isfinite(m.ior) && m.ior > 0 ? m.ior : 1.0f;
  w.exponent = std::isfinite(m.shininess) ? std::clamp(m.shininess, 0.0f, 1e6f) : 1.0f;
  // Per-channel weights scaled so that no channel reflects more than it receives.
  color3 zero = {0, 0, 0};
  w.kd = max(m.kd, zero), w.ks = max(m.ks, zero), w.kr = max(m.kr, zero), w.kt = max(m.kt, zero);
  color3 total = w.kd + w.ks + w.kr + w.kt;
  color3 scale = {1 / std::max(1.0f, total.x), 1 / std::max(1.0f, total.y), 1 / std::max(1.0f, total.z)};
  w.kd *= scale, w.ks *= scale, w.kr *= scale, w.kt *= scale;
  float sum = mean(w.kd) + mean(w.ks) + mean(w.kr) + mean(w.kt);
  if (!(sum > 0) || !std::isfinite(sum)) return w;
  w.p_diffuse = mean(w.kd) / sum;
  w.p_glossy = mean(w.ks) / sum;
  w.p_mirror = mean(w.kr) / sum;
  w.p_transmission = mean(w.kt) / sum;
  w.scatters = true;
  return w;
}

PhongLobes make_phong_lobes(const PhongWeights& w, vec3 n, vec3 wo) {
  PhongLobes l;
  static_cast<PhongWeights&>(l) = w;
  FacingFrame facing = facing_frame(n, wo, w.ior);
  l.frame = facing.frame, l.wo = facing.wo, l.eta = facing.eta;
  l.valid = w.scatters && l.wo.z > 1e-7f && is_finite(l.wo);
  return l;
}

color3 eval_local(const PhongLobes& l, vec3 wi) {
  if (!l.valid || wi.z < 1e-7f) return {0, 0, 0};
  color3 f = l.kd * inv_pi;
  if (l.p_glossy > 0) f += l.ks * ((l.exponent + 2) / (2 * pi) * phong_lobe(l, wi));  // skip pow for matte
  return f * wi.z;
}

float pdf_local(const PhongLobes& l, vec3 wi) {
  if (!l.valid || wi.z < 1e-7f) return 0;
  float pdf = l.p_diffuse * wi.z * inv_pi;
  if (l.p_glossy > 0) pdf += l.p_glossy * (l.exponent + 1) / (2 * pi) * phong_lobe(l, wi);
  return pdf;
}

std::optional<BsdfSample> sample_local(const PhongLobes& l, float u_lobe, vec2 u, const vec3* cosine) {
  if (!l.valid) return std::nullopt;
  float threshold = l.p_diffuse;
  if (u_lobe < threshold) return mixture_sample(l, cosine ? *cosine : sample_cosine_hemisphere(u));
  if (u_lobe < (threshold += l.p_glossy)) return mixture_sample(l, sample_phong_lobe(l.wo, l.exponent, u));
  if (u_lobe < (threshold += l.p_mirror)) return delta_sample(l, reflect_local(l.wo), l.kr, l.p_mirror);
  if (l.p_transmission > 0) return sample_delta_transmission(l);
  return std::nullopt;
}

}  // namespace radiant
