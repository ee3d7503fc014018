// The glTF metallic-roughness BSDF: a mix, by metallic and transmission, of a GGX metal, a
// dielectric coating over Lambert ("plastic") and a dielectric interface (glass), see
// docs/materials.md. Lobes are written in the local frame where wo is above the surface.
#include "materials/bsdf_models.h"
#include "materials/lobe_sampling.h"
#include "materials/fresnel.h"
#include "materials/metallic_roughness.h"
#include "materials/metallic_roughness_terms.h"
#include "materials/microfacet.h"
#include "materials/shading_frame.h"

namespace radiant {

namespace {

// The exact Fresnel curve of the coating's ior, rescaled to run from 0 at normal incidence to 1
// at grazing.
[[gnu::always_inline]] inline float coating_rise(const MetallicRoughnessLobes& l, float cos) {
  return fresnel_rise(cos, l.ior, l.ior_f0);
}

// The plastic's coating reflectance (KHR_materials_specular): that curve (its value `rise` at
// `cos`) run from the tinted F0 at normal incidence to 1 at grazing, times its strength. With
// iridescence, a share of it is the thin film's reflectance over that F0 instead.
[[gnu::always_inline]] inline color3 coating_fresnel(const MetallicRoughnessLobes& l, float cos, float rise) {
  color3 f = tinted_coating_reflectance(l.specular_f0, rise);
  if (l.iridescence > 0) f = lerp(f, thin_film_fresnel(cos, l.film_outside_ior, l.film, l.specular_f0), l.iridescence);
  return f * l.specular;
}
[[gnu::always_inline]] inline color3 coating_fresnel(const MetallicRoughnessLobes& l, float cos) {
  return coating_fresnel(l, cos, coating_rise(l, cos));
}

// The metal's reflectance: Schlick's with F0 = base colour, or in part the thin film's over it.
[[gnu::always_inline]] inline color3 metal_fresnel(const MetallicRoughnessLobes& l, float cos) {
  color3 f = fresnel_schlick(l.base, cos);
  if (l.iridescence > 0) f = lerp(f, thin_film_fresnel(cos, l.film_outside_ior, l.film, l.base), l.iridescence);
  return f;
}

// Fresnel reflectance of the mixed specular lobe at microfacet cosine `cos_h`, given the
// coating's curve there (coating_rise; read only when the material has a plastic share).
[[gnu::always_inline]] inline color3 specular_fresnel(const MetallicRoughnessLobes& l, float cos_h, float rise) {
  float glass = l.glass > 0 ? l.glass * fresnel_dielectric(cos_h, l.eta) : 0;
  color3 plastic = l.plastic > 0 ? coating_fresnel(l, cos_h, rise) * l.plastic : color3{0, 0, 0};
  color3 metal = l.metal > 0 ? metal_fresnel(l, cos_h) * l.metal : color3{0, 0, 0};
  return metal + plastic + color3{glass, glass, glass};
}
[[gnu::always_inline]] inline color3 specular_fresnel(const MetallicRoughnessLobes& l, float cos_h) {
  return specular_fresnel(l, cos_h, l.plastic > 0 ? coating_rise(l, cos_h) : 0);
}

// The GGX terms, anisotropic (KHR_materials_anisotropy) only where the material is. Lambda along
// wo is the lobes' own (l.lambda_o): each masking term needs it.
[[gnu::always_inline]] inline float microfacet_density(const MetallicRoughnessLobes& l, vec3 h) {
  return l.anisotropic ? ggx_distribution(h, l.anisotropic_alpha) : ggx_distribution(h, l.alpha);
}
[[gnu::always_inline]] inline float microfacet_lambda(const MetallicRoughnessLobes& l, vec3 w) {
  return l.anisotropic ? ggx_lambda(w, l.anisotropic_alpha) : ggx_lambda(w, l.alpha);
}
[[gnu::always_inline]] inline float microfacet_masking_shadowing(const MetallicRoughnessLobes& l, vec3 wi) {
  return ggx_masking_shadowing_of(l.lambda_o, microfacet_lambda(l, wi));
}
// The density of visible normals h (Heitz 2018), given h's density.
[[gnu::always_inline]] inline float visible_normal_pdf(const MetallicRoughnessLobes& l, vec3 h, float density) {
  return ggx_visible_density(l.wo, h, l.lambda_o, density);
}
vec3 sample_visible_normal(const MetallicRoughnessLobes& l, vec2 u) {
  return l.anisotropic ? sample_ggx_visible_normal(l.wo, l.anisotropic_alpha, u) : sample_ggx_visible_normal(l.wo, l.alpha, u);
}

// Between equal indices a rough interface neither reflects (F = 0) nor bends light: Walter's
// lobe narrows to the straight line as eta -> 1 (pbrt-v4 makes eta = 1 specular too), and close
// to 1 its generalized half vector, of length ~|eta - 1|, is lost to rounding.
constexpr float index_matched_tolerance = 1e-3f;
bool is_index_matched(float ior) { return std::abs(ior - 1) < index_matched_tolerance; }
bool transmission_is_delta(const MetallicRoughnessLobes& l) { return l.smooth || is_index_matched(l.ior); }

// Generalized half vector of a refraction (Walter et al. 2007), facing the wo side; false when
// wo and wi cannot be joined by a refracting microfacet.
bool refraction_half_vector(const MetallicRoughnessLobes& l, vec3 wi, vec3& h) {
  h = l.wo + wi * l.eta;
  if (length_squared(h) < 1e-12f) return false;
  h = normalize(h);
  if (h.z < 0) h = -h;
  return dot(l.wo, h) > 0 && dot(wi, h) < 0;
}

// The rough lobes add their f(wo, wi) * |cos| to `f` and their share of the pdf to `pdf`, each
// only when asked: evaluating both shares the half vector and the microfacet density.
template <bool WithF, bool WithPdf>
[[gnu::always_inline]] inline void add_rough_reflection(const MetallicRoughnessLobes& l, vec3 wi, color3& f, float& pdf) {
  vec3 h = normalize(l.wo + wi);
  float cos_h = dot(l.wo, h);
  if (cos_h <= 0) return;
  float density = microfacet_density(l, h);
  if constexpr (WithF) f += specular_fresnel(l, cos_h) * (density * microfacet_masking_shadowing(l, wi) / (4 * l.wo.z));
  if constexpr (WithPdf) pdf += l.p_specular * (visible_normal_pdf(l, h, density) / (4 * cos_h));
}

// The squared denominator of the refraction Jacobian, or 0 when degenerate.
float refraction_denominator(const MetallicRoughnessLobes& l, vec3 wi, vec3 h) {
  float denominator = dot(wi, h) + dot(l.wo, h) / l.eta;
  return denominator * denominator;
}

// The glass lobe samples a visible microfacet, then reflects with that microfacet's Fresnel
// reflectance F and refracts otherwise (as pbrt-v4's rough dielectric does): where the interface
// reflects most, beyond the critical angle inside, its sample reflects instead of dying, and
// neither choice's weight grows with 1 / F. These are its pdfs of each side.
template <bool WithF, bool WithPdf>
void add_rough_transmission(const MetallicRoughnessLobes& l, vec3 wi, color3& f, float& pdf) {
  vec3 h;
  if (!refraction_half_vector(l, wi, h)) return;
  float denominator = refraction_denominator(l, wi, h);
  if (denominator < 1e-12f) return;
  float density = microfacet_density(l, h);
  float cos_h = dot(l.wo, h), transmitted = 1 - fresnel_dielectric(cos_h, l.eta);
  if constexpr (WithF) {
    float g = density * microfacet_masking_shadowing(l, wi) * std::abs(dot(wi, h)) * cos_h / (l.wo.z * denominator);
    f += l.base * (l.glass * transmitted * g);
  }
  if constexpr (WithPdf)
    pdf += l.p_transmission * transmitted * (visible_normal_pdf(l, h, density) * std::abs(dot(wi, h)) / denominator);
}
float glass_reflection_pdf(const MetallicRoughnessLobes& l, vec3 wi) {
  vec3 h = normalize(l.wo + wi);
  float cos_h = dot(l.wo, h);
  if (cos_h <= 0) return 0;
  return fresnel_dielectric(cos_h, l.eta) * visible_normal_pdf(l, h, microfacet_density(l, h)) / (4 * cos_h);
}

// f(wo, wi) * |cos| of the non-delta lobes, and the pdf that sample_local picks wi through them,
// each only when asked (0 where not finite).
template <bool WithF, bool WithPdf>
color3 evaluate(const MetallicRoughnessLobes& l, vec3 wi, float& pdf) {
  color3 f;
  pdf = 0;
  if (!l.valid || std::abs(wi.z) < 1e-7f) return f;
  if (wi.z > 0) {
    if (WithF && l.p_diffuse > 0) f += eval_cosine_lobes(l.energy, l.diffuse, l.plastic, l.coating_o, l.loss_o, wi.z);
    if (WithPdf) pdf += l.p_diffuse * wi.z * inv_pi;
    if (!l.smooth && l.p_specular > 0) add_rough_reflection<WithF, WithPdf>(l, wi, f, pdf);
    if (WithPdf && !transmission_is_delta(l) && l.p_transmission > 0) pdf += l.p_transmission * glass_reflection_pdf(l, wi);
  } else {
    if (l.p_diffuse_transmission > 0) {
      if (WithF)
        f += eval_coated_diffuse(l.energy, l.diffuse_transmitted, l.plastic, l.coating_o, -wi.z,
                                 microfacet_albedos(l.energy, -wi.z));
      if (WithPdf) pdf += l.p_diffuse_transmission * -wi.z * inv_pi;
    }
    if (!transmission_is_delta(l) && l.p_transmission > 0) add_rough_transmission<WithF, WithPdf>(l, wi, f, pdf);
  }
  if (!std::isfinite(pdf)) pdf = 0;
  return is_finite(f) ? f : color3{0, 0, 0};
}

std::optional<BsdfSample> sample_specular(const MetallicRoughnessLobes& l, vec2 u) {
  if (l.smooth) return delta_sample(l, reflect_local(l.wo), specular_fresnel(l, l.wo.z), l.p_specular);
  vec3 h = sample_visible_normal(l, u);
  vec3 wi = reflect(l.wo, h);
  if (wi.z <= 0) return std::nullopt;  // the microfacet sends light below the surface: masked
  return mixture_sample(l, wi);
}

// `u_choice` in [0, 1) picks reflection or refraction at the sampled microfacet.
std::optional<BsdfSample> sample_transmission(const MetallicRoughnessLobes& l, float u_choice, vec2 u) {
  vec3 wi;
  if (transmission_is_delta(l)) {
    if (!refract(l.wo, {0, 0, 1}, l.eta, wi)) return std::nullopt;  // reflection took it all
    color3 transmittance = l.base * (l.glass * (1 - fresnel_dielectric(l.wo.z, l.eta)));
    return delta_sample(l, wi, transmittance, l.p_transmission);
  }
  vec3 h = sample_visible_normal(l, u);
  if (u_choice < fresnel_dielectric(dot(l.wo, h), l.eta)) {  // 1 where refract() would fail
    wi = reflect(l.wo, h);
    if (wi.z <= 0) return std::nullopt;  // sent below the surface: masked
    return mixture_sample(l, wi);
  }
  if (!refract(l.wo, h, l.eta, wi) || wi.z >= 0) return std::nullopt;
  return mixture_sample(l, normalize(wi));
}

}  // namespace

MetallicRoughnessParams make_metallic_roughness_params(const SurfaceMaterial& m) {
  MetallicRoughnessParams p;
  p.alpha = roughness_to_alpha(m.roughness);
  // KHR_materials_anisotropy: rougher along the anisotropy direction, alpha_t = lerp(alpha, 1, s^2).
  float anisotropy = std::clamp(m.anisotropy, 0.0f, 1.0f);
  p.anisotropic = anisotropy > 0;
  p.anisotropic_alpha = {p.alpha + (1 - p.alpha) * anisotropy * anisotropy, std::max(p.alpha, smooth_alpha_threshold)};
  p.smooth = (p.anisotropic ? p.anisotropic_alpha.x : p.alpha) < smooth_alpha_threshold;
  p.ior = std::isfinite(m.ior) && m.ior > 0 ? m.ior : 1.5f;
  p.base = min(max(m.base_color, {0, 0, 0}), {1, 1, 1});
  float metallic = std::clamp(m.metallic, 0.0f, 1.0f), transmission = std::clamp(m.transmission, 0.0f, 1.0f);
  p.metal = metallic;
  p.plastic = (1 - metallic) * (1 - transmission);
  p.glass = (1 - metallic) * transmission;
  float diffuse_transmission = std::clamp(m.diffuse_transmission, 0.0f, 1.0f);
  p.diffuse = p.base * (1 - diffuse_transmission);
  p.diffuse_transmitted = min(max(m.diffuse_transmission_color, {0, 0, 0}), {1, 1, 1}) * diffuse_transmission;
  p.specular = std::clamp(m.specular, 0.0f, 1.0f);
  p.specular_f0 = tinted_dielectric_f0(p.ior, m.specular_color);
  p.specular_f0_max = max_component(p.specular_f0);
  p.ior_f0 = dielectric_f0(p.ior);
  p.iridescence = std::clamp(m.iridescence, 0.0f, 1.0f);
  p.film = {m.iridescence_ior, std::max(m.iridescence_thickness, 0.0f)};
  // The clearcoat extension puts its coat (ior 1.5) above the film.
  p.film_outside_ior = m.clearcoat > 0 ? 1.5f : 1.0f;
  // The albedo tables are isotropic: an anisotropic lobe takes the mean of its alphas. Its
  // loss is nearer the lobe's than the geometric mean's (a brushed metal kept 0.65 of the light).
  float alpha = p.anisotropic ? (p.anisotropic_alpha.x + p.anisotropic_alpha.y) / 2 : p.alpha;
  p.energy = make_microfacet_energy(alpha, p.smooth, p.ior, p.metal, p.base, p.plastic, p.specular, p.specular_f0);
  return p;
}

MetallicRoughnessLobes make_metallic_roughness_lobes(const MetallicRoughnessParams& params, vec3 n, vec3 wo,
                                                     vec3 tangent) {
  MetallicRoughnessLobes l;
  static_cast<MetallicRoughnessParams&>(l) = params;
  FacingFrame facing = facing_frame(n, wo, l.ior, l.anisotropic ? tangent : vec3{});
  l.frame = facing.frame, l.wo = facing.wo, l.eta = facing.eta;
  if (!(l.wo.z > 1e-7f) || !is_finite(l.wo)) return l;
  bool colored = max_component(l.base) > 0;
  float cos_o = l.wo.z;
  l.loss_o = ggx_energy_loss(l.energy, cos_o);
  l.coating_o = coating_passage(l.energy, cos_o, l.loss_o);
  if (!l.smooth) l.lambda_o = microfacet_lambda(l, l.wo);
  float specular = selection_weight(l.metal > 0 || l.plastic * l.specular > 0 || (l.glass > 0 && !is_index_matched(l.ior)),
                                    mean(specular_fresnel(l, cos_o)), l.smooth);
  // The diffuse and the multiple scattering share the cosine hemisphere.
  float diffuse = selection_weight(has_cosine_lobes(l), cosine_lobes_albedo(l.energy, l.diffuse, l.plastic, l.coating_o, l.loss_o),
                                   false);
  float diffuse_transmitted = selection_weight(l.plastic > 0 && max_component(l.diffuse_transmitted) > 0,
                                               l.plastic * mean(l.diffuse_transmitted) * l.coating_o, false);
  // A rough glass lobe reflects too, where its microfacets choose to: its estimate counts both.
  float glass_f = fresnel_dielectric(cos_o, l.eta), glass_reflects = transmission_is_delta(l) ? 0 : glass_f;
  float transmitted = l.glass > 0 && colored ? l.glass * (mean(l.base) * (1 - glass_f) + glass_reflects) : 0;
  transmitted = selection_weight(l.glass > 0 && colored, transmitted, transmission_is_delta(l));
  float total = specular + diffuse + diffuse_transmitted + transmitted;
  if (total <= 0) return l;
  l.p_specular = specular / total;
  l.p_diffuse = diffuse / total;
  l.p_diffuse_transmission = diffuse_transmitted / total;
  l.p_transmission = transmitted / total;
  l.valid = true;
  return l;
}

color3 eval_local(const MetallicRoughnessLobes& l, vec3 wi) {
  float unused;
  return evaluate<true, false>(l, wi, unused);
}

float pdf_local(const MetallicRoughnessLobes& l, vec3 wi) {
  float pdf;
  evaluate<false, true>(l, wi, pdf);
  return pdf;
}

color3 eval_with_pdf(const MetallicRoughnessLobes& l, vec3 wi, float& pdf) { return evaluate<true, true>(l, wi, pdf); }

std::optional<BsdfSample> sample_local(const MetallicRoughnessLobes& l, float u_lobe, vec2 u, const vec3* cosine) {
  if (!l.valid) return std::nullopt;
  if (u_lobe < l.p_specular) return sample_specular(l, u);
  if (u_lobe < l.p_specular + l.p_diffuse) return mixture_sample(l, cosine ? *cosine : sample_cosine_hemisphere(u));
  float u_rest = u_lobe - l.p_specular - l.p_diffuse;
  if (l.p_diffuse_transmission > 0 && u_rest < l.p_diffuse_transmission) {
    vec3 below = cosine ? *cosine : sample_cosine_hemisphere(u);
    return mixture_sample(l, {below.x, below.y, -below.z});
  }
  // The rest of u_lobe chooses the glass's reflection or refraction. It is drawn: rough glass that
  // is not index-matched always has the specular lobe beside it.
  if (l.p_transmission > 0)
    return sample_transmission(l, std::min((u_rest - l.p_diffuse_transmission) / l.p_transmission, 0x1.fffffep-1f), u);
  return std::nullopt;
}

bool is_metallic_roughness_pure_delta(const SurfaceMaterial& m) {
  float alpha = roughness_to_alpha(m.roughness), anisotropy = std::clamp(m.anisotropy, 0.0f, 1.0f);
  float widest_alpha = alpha + (1 - alpha) * anisotropy * anisotropy;  // alpha itself when isotropic
  bool clear_glass = m.metallic <= 0 && m.transmission >= 1 && is_index_matched(m.ior);  // straight through only
  return clear_glass || (widest_alpha < smooth_alpha_threshold && !has_metallic_roughness_diffuse(m));
}

}  // namespace radiant
