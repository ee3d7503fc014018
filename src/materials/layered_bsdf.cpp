// The layered metallic-roughness BSDF: KHR_materials_clearcoat's clear GGX coat over
// KHR_materials_sheen's Charlie sheen over the base, combined as the extensions state: each layer
// reflects its share and the layers below get what it lets through, on the way in and on the
// way out (docs/materials.md).
#include "materials/bsdf_models.h"
#include "materials/fresnel.h"
#include "materials/lobe_sampling.h"
#include "materials/metallic_roughness.h"
#include "materials/microfacet.h"
#include "materials/sheen.h"

namespace radiant {

namespace {

constexpr float coat_ior = 1.5f;  // fixed by the clearcoat extension
// Smallest selection probability of a present non-delta layer (its pdf must not vanish where it scatters).
constexpr float min_selection = 0.05f;

float coat_reflectance(const LayeredLobes& l, float cos) { return l.coat * fresnel_dielectric(std::abs(cos), coat_ior); }

// A direction in the base's frame seen in the coat's, and back.
vec3 to_coat(const LayeredLobes& l, vec3 w) { return l.own_coat_frame ? to_local(l.coat_frame, to_world(l.frame, w)) : w; }
vec3 from_coat(const LayeredLobes& l, vec3 w) { return l.own_coat_frame ? to_local(l.frame, to_world(l.coat_frame, w)) : w; }

// What the coat lets through at cosine `cos`; the product over wo and wi keeps reciprocity.
float coat_transmittance(const LayeredLobes& l, float cos) { return 1 - coat_reflectance(l, cos); }

// What the sheen leaves the base: the extension's min(1 − max(colour)·E(cosθo), 1 − max(colour)·E(cosθi)).
float sheen_transmittance(const LayeredLobes& l, float cos_i) {
  if (l.sheen_max <= 0) return 1;
  float e_i = sheen_albedo(std::abs(cos_i), l.sheen_roughness);
  return 1 - l.sheen_max * std::max(l.sheen_albedo_o, e_i);
}

// The coat lobe, with wi in the coat's frame.
color3 eval_coat(const LayeredLobes& l, vec3 wi) {
  vec3 h = normalize(l.coat_wo + wi);
  float cos_h = dot(l.coat_wo, h);
  if (cos_h <= 0) return {0, 0, 0};
  float f = ggx_distribution(h, l.coat_alpha) * ggx_masking_shadowing(l.coat_wo, wi, l.coat_alpha) *
            coat_reflectance(l, cos_h) / (4 * l.coat_wo.z);
  return {f, f, f};
}

float pdf_coat(const LayeredLobes& l, vec3 wi) {
  vec3 h = normalize(l.coat_wo + wi);
  float cos_h = dot(l.coat_wo, h);
  if (cos_h <= 0) return 0;
  return ggx_visible_normal_pdf(l.coat_wo, h, l.coat_alpha) / (4 * cos_h);
}

std::optional<BsdfSample> sample_coat(const LayeredLobes& l, vec2 u) {
  if (l.coat_smooth) {
    float r = coat_reflectance(l, l.coat_wo.z);
    return delta_sample(l, from_coat(l, reflect_local(l.coat_wo)), {r, r, r}, l.p_coat);
  }
  vec3 wi = reflect(l.coat_wo, sample_ggx_visible_normal(l.coat_wo, l.coat_alpha, u));
  if (wi.z <= 0) return std::nullopt;
  return mixture_sample(l, from_coat(l, wi));
}

}  // namespace

LayeredParams make_layered_params(const SurfaceMaterial& m) {
  LayeredParams p;
  p.base = make_metallic_roughness_params(m);
  p.coat = std::clamp(m.clearcoat, 0.0f, 1.0f);
  p.coat_alpha = roughness_to_alpha(m.clearcoat_roughness);
  p.coat_smooth = p.coat_alpha < smooth_alpha_threshold;
  p.sheen = min(max(m.sheen_color, {0, 0, 0}), {1, 1, 1});
  p.sheen_roughness = std::clamp(m.sheen_roughness, 0.0f, 1.0f);
  return p;
}

LayeredLobes make_layered_lobes(const LayeredParams& params, vec3 n, vec3 wo, vec3 tangent, vec3 coat_normal) {
  LayeredLobes l;
  static_cast<LayeredParams&>(l) = params;
  l.base_lobes = make_metallic_roughness_lobes(params.base, n, wo, tangent);
  l.frame = l.base_lobes.frame, l.wo = l.base_lobes.wo;
  l.coat_frame = l.frame, l.coat_wo = l.wo;
  if (!(l.wo.z > 1e-7f) || !is_finite(l.wo)) return l;
  if (l.coat > 0 && length_squared(coat_normal) > 0.5f && is_finite(coat_normal)) {
    // On the side the base's frame faces (a transmissive base seen from inside flips it).
    l.coat_frame = make_shading_frame(dot(coat_normal, l.frame.n) < 0 ? -coat_normal : coat_normal);
    l.coat_wo = to_local(l.coat_frame, wo);
    l.own_coat_frame = true;
  }
  l.sheen_max = max_component(l.sheen);
  l.sheen_albedo_o = l.sheen_max > 0 ? sheen_albedo(l.wo.z, l.sheen_roughness) : 0;
  // Selection in proportion to each layer's reflectance at wo and what reaches the base; a coat
  // tilted away from wo reflects nothing.
  float through_coat = coat_transmittance(l, l.coat_wo.z);
  float coat = l.coat_wo.z > 1e-7f ? coat_reflectance(l, l.coat_wo.z) : 0;
  float sheen = through_coat * l.sheen_max * l.sheen_albedo_o;
  float base = l.base_lobes.valid ? through_coat * (1 - l.sheen_max * l.sheen_albedo_o) *
                                        std::max(mean(l.base_lobes.base), 0.1f)
                                  : 0;
  if (coat > 0 && !l.coat_smooth) coat = std::max(coat, min_selection * (coat + sheen + base));
  if (sheen > 0) sheen = std::max(sheen, min_selection * (coat + sheen + base));
  float total = coat + sheen + base;
  if (!(total > 0)) return l;
  l.p_coat = coat / total;
  l.p_sheen = sheen / total;
  l.valid = true;
  return l;
}

color3 eval_local(const LayeredLobes& l, vec3 wi) {
  if (!l.valid || std::abs(wi.z) < 1e-7f) return {0, 0, 0};
  color3 below = eval_local(l.base_lobes, wi) * sheen_transmittance(l, wi.z);
  if (wi.z > 0 && l.sheen_max > 0) below += l.sheen * eval_sheen(l.wo, wi, l.sheen_roughness);
  vec3 wi_coat = to_coat(l, wi);
  color3 f = below * (coat_transmittance(l, l.coat_wo.z) * coat_transmittance(l, wi_coat.z));
  if (!l.coat_smooth && wi_coat.z > 0 && l.p_coat > 0) f += eval_coat(l, wi_coat);
  return is_finite(f) ? f : color3{0, 0, 0};
}

float pdf_local(const LayeredLobes& l, vec3 wi) {
  if (!l.valid || std::abs(wi.z) < 1e-7f) return 0;
  float pdf = (1 - l.p_coat - l.p_sheen) * pdf_local(l.base_lobes, wi);
  vec3 wi_coat = to_coat(l, wi);
  if (wi_coat.z > 0 && !l.coat_smooth && l.p_coat > 0) pdf += l.p_coat * pdf_coat(l, wi_coat);
  if (wi.z > 0) pdf += l.p_sheen * wi.z * inv_pi;  // the sheen is sampled by the cosine-weighted hemisphere
  return std::isfinite(pdf) ? pdf : 0;
}

std::optional<BsdfSample> sample_local(const LayeredLobes& l, float u_lobe, vec2 u, const vec3* cosine) {
  if (!l.valid) return std::nullopt;
  if (u_lobe < l.p_coat) return sample_coat(l, u);
  if (u_lobe < l.p_coat + l.p_sheen) return mixture_sample(l, cosine ? *cosine : sample_cosine_hemisphere(u));
  // The rest of u_lobe chooses among the base's lobes.
  float p_base = 1 - l.p_coat - l.p_sheen;
  float u_base = std::min((u_lobe - l.p_coat - l.p_sheen) / p_base, 0x1.fffffep-1f);
  std::optional<BsdfSample> s = sample_local(l.base_lobes, u_base, u, cosine);
  if (!s) return std::nullopt;
  vec3 wi = to_local(l.frame, s->wi);
  if (!s->delta) return mixture_sample(l, wi);
  // A delta lobe of the base: through the sheen and the coat on the way in and on the way out.
  s->weight *= sheen_transmittance(l, wi.z) * coat_transmittance(l, l.coat_wo.z) *
               coat_transmittance(l, to_coat(l, wi).z) / p_base;
  s->pdf *= p_base;
  return s;
}

}  // namespace radiant
