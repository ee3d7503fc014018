// The BSDF families behind materials/bsdf.h. Each has a part that depends on the material
// only (worked out once per material when it has no textures) and its lobes seen from one
// outgoing direction: that part plus the local frame and what depends on wo, then evaluated,
// queried for pdfs and sampled in that frame (Lambert needs no frame but to sample).
#pragma once

#include <optional>

#include "materials/microfacet_energy.h"
#include "materials/shading_frame.h"
#include "materials/surface.h"
#include "materials/thin_film.h"

namespace radiant {

// Lambert: the matte surface (a Phong material with only kd). The commonest surface gets its
// own model because it needs no local frame to evaluate, only to sample, and no lobe choice.
struct LambertParams {
  color3 albedo;  // the energy-conserving kd
};
struct LambertLobes : LambertParams {
  bool valid = false;
  vec3 n;  // the normal on wo's side
};
LambertLobes make_lambert_lobes(const LambertParams& params, vec3 n, vec3 wo);
// Below this cosine a direction counts as grazing and carries nothing (as in the Phong model).
constexpr float lambert_min_cosine = 1e-7f;
// These take world-space directions. Inline, as Bsdf's Lambertian branches are (bsdf.h).
[[gnu::always_inline]] inline color3 eval_world(const LambertLobes& l, vec3 wi) {
  float cos_i = dot(l.n, wi);
  if (!l.valid || !(cos_i >= lambert_min_cosine)) return {0, 0, 0};
  return l.albedo * (inv_pi * cos_i);
}
[[gnu::always_inline]] inline color3 eval_world(const LambertLobes& l, vec3 wi, float& pdf) {  // and pdf_world in `pdf`
  float cos_i = dot(l.n, wi);
  pdf = 0;
  if (!l.valid || !(cos_i >= lambert_min_cosine)) return {0, 0, 0};
  pdf = cos_i * inv_pi;
  return l.albedo * (inv_pi * cos_i);
}
inline float pdf_world(const LambertLobes& l, vec3 wi) {
  float cos_i = dot(l.n, wi);
  if (!l.valid || !(cos_i >= lambert_min_cosine)) return 0;
  return cos_i * inv_pi;
}
std::optional<BsdfSample> sample_world(const LambertLobes& l, vec2 u);
// sample_world with `local` = sample_cosine_hemisphere(u) already worked out.
std::optional<BsdfSample> sample_warped(const LambertLobes& l, vec3 local);

// Phong: normalized diffuse + modified-Phong lobe, delta mirror (kr) and delta transmission (kt).
// The weights and lobe choice depend on the material only.
struct PhongWeights {
  bool scatters = false;  // some lobe has weight
  float ior = 1;
  float exponent = 1;
  color3 kd, ks, kr, kt;  // energy-conserving weights
  float p_diffuse = 0, p_glossy = 0, p_mirror = 0, p_transmission = 0;
};
PhongWeights make_phong_weights(const SurfaceMaterial& m);
// The modified Phong lobe's cos^n, from the cosine of the angle between wi and wo's mirror
// direction (0 beyond 90 degrees).
float phong_lobe_power(float cos_alpha, float exponent);
// A local direction with density (n+1)/(2 pi) cos^n around the mirror direction of local `wo`.
vec3 sample_phong_lobe(vec3 wo, float exponent, vec2 u);
struct PhongLobes : PhongWeights {
  bool valid = false;
  ShadingFrame frame;  // z = the normal on wo's side
  vec3 wo;             // local, wo.z > 0
  float eta = 1.5f;    // n_transmitted / n_incident seen from wo
};
PhongLobes make_phong_lobes(const PhongWeights& w, vec3 n, vec3 wo);
color3 eval_local(const PhongLobes& l, vec3 wi);
float pdf_local(const PhongLobes& l, vec3 wi);
std::optional<BsdfSample> sample_local(const PhongLobes& l, float u_lobe, vec2 u, const vec3* cosine = nullptr);
inline bool is_phong_pure_delta(const SurfaceMaterial& m) {
  return max_component(m.kd) <= 0 && max_component(m.ks) <= 0;
}

// glTF metallic-roughness: GGX specular over Lambert, metal, and (rough or smooth) transmission.
// The parameters depend on the material only; the lobe choice also on wo (Fresnel).
struct MetallicRoughnessParams {
  float alpha = 1;
  bool anisotropic = false;     // KHR_materials_anisotropy: GGX with anisotropic_alpha in the lobe frame
  vec2 anisotropic_alpha;       // along the frame's x (the anisotropy direction) and y
  bool smooth = false;  // specular lobes are delta
  float ior = 1.5f;     // of the coating, always entered from outside
  color3 base;
  float metal = 0, plastic = 0, glass = 0;  // mix weights, summing to 1
  // The plastic's Lambertian base (KHR_materials_diffuse_transmission's mix): `diffuse`
  // reflects (base × (1 − share)), `diffuse_transmitted` leaves into the other hemisphere
  // (the extension's colour × share); both lie under the same coating.
  color3 diffuse;
  color3 diffuse_transmitted;
  // The plastic's Fresnel coating (KHR_materials_specular): its strength, its tinted F0, and
  // the untinted F0 of the ior that the exact Fresnel curve is rescaled from.
  float specular = 1;
  color3 specular_f0 = {0.04f, 0.04f, 0.04f};
  float specular_f0_max = 0.04f;  // its largest channel
  float ior_f0 = 0.04f;
  // KHR_materials_iridescence: the share of the thin film's Fresnel in the metal's and the
  // plastic's specular reflection, the film, and the index above it (1.5 under a clearcoat).
  float iridescence = 0;
  ThinFilm film;
  float film_outside_ior = 1;
  // Multiple scattering of the metal and the coating, and the diffuse's share of what the coating
  // lets through (microfacet_energy.h).
  MicrofacetEnergy energy;
};
MetallicRoughnessParams make_metallic_roughness_params(const SurfaceMaterial& m);
struct MetallicRoughnessLobes : MetallicRoughnessParams {
  bool valid = false;
  ShadingFrame frame;  // z = the normal on wo's side
  vec3 wo;             // local, wo.z > 0
  float eta = 1.5f;    // of the glass: n_transmitted / n_incident seen from wo
  float p_specular = 0, p_diffuse = 0, p_transmission = 0;
  float p_diffuse_transmission = 0;  // the cosine hemisphere below the surface
  float coating_o = 1;  // 1 − the coating's albedo along wo: every diffuse eval needs it
  float loss_o = 0;     // 1 − the GGX albedo along wo: every multiple-scattering eval needs it
  float lambda_o = 0;   // Smith's GGX Lambda along wo (rough lobes): every masking term needs it
};
// `tangent` (world space, any length; zero when unknown) orients an anisotropic lobe's frame.
MetallicRoughnessLobes make_metallic_roughness_lobes(const MetallicRoughnessParams& params, vec3 n, vec3 wo,
                                                     vec3 tangent = {});
color3 eval_local(const MetallicRoughnessLobes& l, vec3 wi);
float pdf_local(const MetallicRoughnessLobes& l, vec3 wi);
// Both at once, sharing the half vector and the microfacet density (lobe_sampling.h).
color3 eval_with_pdf(const MetallicRoughnessLobes& l, vec3 wi, float& pdf);
std::optional<BsdfSample> sample_local(const MetallicRoughnessLobes& l, float u_lobe, vec2 u,
                                       const vec3* cosine = nullptr);
// The lobes the cosine hemisphere samples (a diffuse base, multiple scattering) are present.
inline bool has_cosine_lobes(const MetallicRoughnessParams& p) {
  return (p.plastic > 0 && max_component(p.diffuse) > 0) || max_component(p.energy.multiple_scattering) > 0;
}
// The material has a diffuse base, reflecting or transmitting (then it is never pure delta).
// Inline: asked at every path vertex.
inline bool has_metallic_roughness_diffuse(const SurfaceMaterial& m) {
  return m.metallic < 1 && m.transmission < 1 &&
         (max_component(m.base_color) > 0 || (m.diffuse_transmission > 0 && max_component(m.diffuse_transmission_color) > 0));
}
bool is_metallic_roughness_pure_delta(const SurfaceMaterial& m);

// KHR_materials_clearcoat and KHR_materials_sheen: a clear dielectric GGX coat (ior 1.5) over a
// Charlie sheen over the metallic-roughness BSDF. Only materials with a coat or a sheen get this
// model, so the others pay nothing for it.
struct LayeredParams {
  MetallicRoughnessParams base;
  float coat = 0;        // clearcoat factor × texture, in [0, 1]
  float coat_alpha = 0;  // the coat's GGX alpha
  bool coat_smooth = false;
  color3 sheen;              // sheen colour × texture
  float sheen_roughness = 0;
};
LayeredParams make_layered_params(const SurfaceMaterial& m);
struct LayeredLobes : LayeredParams {
  MetallicRoughnessLobes base_lobes;
  bool valid = false;
  ShadingFrame frame;  // the base's frame: z = the normal on wo's side
  vec3 wo;             // local, wo.z > 0
  // The coat's frame when it has a normal of its own (KHR_materials_clearcoat's normal texture),
  // and wo in it; otherwise the base's frame and wo.
  bool own_coat_frame = false;
  ShadingFrame coat_frame;
  vec3 coat_wo;
  float sheen_max = 0, sheen_albedo_o = 0;  // max(sheen colour), E(cosθo)
  float p_coat = 0, p_sheen = 0;            // selection; the base gets the rest
};
// `coat_normal` (world, on n's side; zero: n) tilts the coat alone.
LayeredLobes make_layered_lobes(const LayeredParams& params, vec3 n, vec3 wo, vec3 tangent = {},
                                vec3 coat_normal = {});
color3 eval_local(const LayeredLobes& l, vec3 wi);
float pdf_local(const LayeredLobes& l, vec3 wi);
std::optional<BsdfSample> sample_local(const LayeredLobes& l, float u_lobe, vec2 u, const vec3* cosine = nullptr);

}  // namespace radiant
