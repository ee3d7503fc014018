// The glTF metallic-roughness BSDF: a mix, by metallic and transmission, of a GGX metal, a
// dielectric coating over Lambert ("plastic") and a dielectric interface (glass), see
// docs/materials.md. Lobes are written in the local frame where wo is above the surface.
#include "materials/bsdf_models.h"
#include "materials/lobe_sampling.h"
#include "materials/fresnel.h"
#include "materials/metallic_roughness.h"
#include "materials/microfacet.h"
#include "materials/shading_frame.h"

namespace radiant {

namespace {

// Smallest selection weight of a present non-delta lobe: its pdf must never be 0 where it scatters.
constexpr float min_lobe_weight = 0.05f;

// Fresnel reflectance of the mixed specular lobe at microfacet cosine `cos_h`.
color3 specular_fresnel(const MetallicRoughnessLobes& l, float cos_h) {
  float dielectric = l.plastic * l.fade * fresnel_dielectric(cos_h, l.ior) +
                     l.glass * fresnel_dielectric(cos_h, l.eta);
  return l.metal * fresnel_schlick(l.base, cos_h) + color3{dielectric, dielectric, dielectric};
}

// Light crossing the plastic's coating at cosine `cos` (symmetric in wo and wi: reciprocity).
float coating_transmittance(const MetallicRoughnessLobes& l, float cos) {
  return 1 - l.fade * fresnel_dielectric(cos, l.ior);
}

// Delta lobes need no floor: a delta lobe with no reflectance is simply never chosen.
float selection_weight(bool present, float estimate, bool delta) {
  if (!present) return 0;
  return delta ? estimate : std::max(estimate, min_lobe_weight);
}

// Generalized half vector of a refraction (Walter et al. 2007), facing the wo side; false when
// wo and wi cannot be joined by a refracting microfacet.
bool refraction_half_vector(const MetallicRoughnessLobes& l, vec3 wi, vec3& h) {
  h = l.wo + wi * l.eta;
  if (length_squared(h) < 1e-12f) return false;
  h = normalize(h);
  if (h.z < 0) h = -h;
  return dot(l.wo, h) > 0 && dot(wi, h) < 0;
}

color3 eval_diffuse(const MetallicRoughnessLobes& l, vec3 wi) {
  float coating = coating_transmittance(l, l.wo.z) * coating_transmittance(l, wi.z);
  return l.base * (l.plastic * coating * inv_pi * wi.z);
}

color3 eval_rough_reflection(const MetallicRoughnessLobes& l, vec3 wi) {
  vec3 h = normalize(l.wo + wi);
  float cos_h = dot(l.wo, h);
  if (cos_h <= 0) return {0, 0, 0};
  float d = ggx_distribution(h, l.alpha) * ggx_masking_shadowing(l.wo, wi, l.alpha);
  return specular_fresnel(l, cos_h) * (d / (4 * l.wo.z));
}

float pdf_rough_reflection(const MetallicRoughnessLobes& l, vec3 wi) {
  vec3 h = normalize(l.wo + wi);
  float cos_h = dot(l.wo, h);
  if (cos_h <= 0) return 0;
  return ggx_visible_normal_pdf(l.wo, h, l.alpha) / (4 * cos_h);
}

// The squared denominator of the refraction Jacobian, or 0 when degenerate.
float refraction_denominator(const MetallicRoughnessLobes& l, vec3 wi, vec3 h) {
  float denominator = dot(wi, h) + dot(l.wo, h) / l.eta;
  return denominator * denominator;
}

color3 eval_rough_transmission(const MetallicRoughnessLobes& l, vec3 wi) {
  vec3 h;
  if (!refraction_half_vector(l, wi, h)) return {0, 0, 0};
  float denominator = refraction_denominator(l, wi, h);
  if (denominator < 1e-12f) return {0, 0, 0};
  float cos_h = dot(l.wo, h);
  float transmittance = l.glass * (1 - fresnel_dielectric(cos_h, l.eta));
  float f = ggx_distribution(h, l.alpha) * ggx_masking_shadowing(l.wo, wi, l.alpha) * std::abs(dot(wi, h)) *
            cos_h / (l.wo.z * denominator);
  return l.base * (transmittance * f);
}

float pdf_rough_transmission(const MetallicRoughnessLobes& l, vec3 wi) {
  vec3 h;
  if (!refraction_half_vector(l, wi, h)) return 0;
  float denominator = refraction_denominator(l, wi, h);
  if (denominator < 1e-12f) return 0;
  return ggx_visible_normal_pdf(l.wo, h, l.alpha) * std::abs(dot(wi, h)) / denominator;
}

std::optional<BsdfSample> sample_specular(const MetallicRoughnessLobes& l, vec2 u) {
  if (l.smooth) return delta_sample(l, reflect_local(l.wo), specular_fresnel(l, l.wo.z), l.p_specular);
  vec3 h = sample_ggx_visible_normal(l.wo, l.alpha, u);
  vec3 wi = reflect(l.wo, h);
  if (wi.z <= 0) return std::nullopt;  // the microfacet sends light below the surface: masked
  return mixture_sample(l, wi);
}

std::optional<BsdfSample> sample_transmission(const MetallicRoughnessLobes& l, vec2 u) {
  vec3 wi;
  if (l.smooth) {
    if (!refract(l.wo, {0, 0, 1}, l.eta, wi)) return std::nullopt;  // reflection took it all
    color3 transmittance = l.base * (l.glass * (1 - fresnel_dielectric(l.wo.z, l.eta)));
    return delta_sample(l, wi, transmittance, l.p_transmission);
  }
  vec3 h = sample_ggx_visible_normal(l.wo, l.alpha, u);
  if (!refract(l.wo, h, l.eta, wi) || wi.z >= 0) return std::nullopt;
  return mixture_sample(l, normalize(wi));
}

}  // namespace

MetallicRoughnessParams make_metallic_roughness_params(const SurfaceMaterial& m) {
  MetallicRoughnessParams p;
  p.alpha = roughness_to_alpha(m.roughness);
  p.smooth = p.alpha < smooth_alpha_threshold;
  p.ior = std::isfinite(m.ior) && m.ior > 0 ? m.ior : 1.5f;
  p.base = min(max(m.base_color, {0, 0, 0}), {1, 1, 1});
  float metallic = std::clamp(m.metallic, 0.0f, 1.0f), transmission = std::clamp(m.transmission, 0.0f, 1.0f);
  p.metal = metallic;
  p.plastic = (1 - metallic) * (1 - transmission);
  p.glass = (1 - metallic) * transmission;
  p.fade = dielectric_specular_fade(m.roughness);
  return p;
}

MetallicRoughnessLobes make_metallic_roughness_lobes(const MetallicRoughnessParams& params, vec3 n, vec3 wo) {
  MetallicRoughnessLobes l;
  static_cast<MetallicRoughnessParams&>(l) = params;
  FacingFrame facing = facing_frame(n, wo, l.ior);
  l.frame = facing.frame, l.wo = facing.wo, l.eta = facing.eta;
  if (!(l.wo.z > 1e-7f) || !is_finite(l.wo)) return l;
  bool colored = max_component(l.base) > 0;
  float cos_o = l.wo.z;
  float specular = selection_weight(l.metal > 0 || l.plastic * l.fade > 0 || l.glass > 0,
                                    mean(specular_fresnel(l, cos_o)), l.smooth);
  float diffuse = selection_weight(l.plastic > 0 && colored,
                                   l.plastic * mean(l.base) * coating_transmittance(l, cos_o), false);
  float transmittance = 1 - fresnel_dielectric(cos_o, l.eta);
  float transmitted =
      selection_weight(l.glass > 0 && colored, l.glass * mean(l.base) * transmittance, l.smooth);
  float total = specular + diffuse + transmitted;
  if (total <= 0) return l;
  l.p_specular = specular / total;
  l.p_diffuse = diffuse / total;
  l.p_transmission = transmitted / total;
  l.valid = true;
  return l;
}

color3 eval_local(const MetallicRoughnessLobes& l, vec3 wi) {
  if (!l.valid || std::abs(wi.z) < 1e-7f) return {0, 0, 0};
  color3 f;
  if (wi.z > 0) {
    if (l.p_diffuse > 0) f += eval_diffuse(l, wi);
    if (!l.smooth && l.p_specular > 0) f += eval_rough_reflection(l, wi);
  } else if (!l.smooth && l.p_transmission > 0) {
    f += eval_rough_transmission(l, wi);
  }
  return is_finite(f) ? f : color3{0, 0, 0};
}

float pdf_local(const MetallicRoughnessLobes& l, vec3 wi) {
  if (!l.valid || std::abs(wi.z) < 1e-7f) return 0;
  float pdf = 0;
  if (wi.z > 0) {
    pdf += l.p_diffuse * wi.z * inv_pi;
    if (!l.smooth && l.p_specular > 0) pdf += l.p_specular * pdf_rough_reflection(l, wi);
  } else if (!l.smooth && l.p_transmission > 0) {
    pdf += l.p_transmission * pdf_rough_transmission(l, wi);
  }
  return std::isfinite(pdf) ? pdf : 0;
}

std::optional<BsdfSample> sample_local(const MetallicRoughnessLobes& l, float u_lobe, vec2 u) {
  if (!l.valid) return std::nullopt;
  if (u_lobe < l.p_specular) return sample_specular(l, u);
  if (u_lobe < l.p_specular + l.p_diffuse) return mixture_sample(l, sample_cosine_hemisphere(u));
  if (l.p_transmission > 0) return sample_transmission(l, u);
  return std::nullopt;
}

bool is_metallic_roughness_pure_delta(const SurfaceMaterial& m) {
  bool has_diffuse = m.metallic < 1 && m.transmission < 1 && max_component(m.base_color) > 0;
  return roughness_to_alpha(m.roughness) < smooth_alpha_threshold && !has_diffuse;
}

}  // namespace radiant
