// The glTF metallic-roughness BSDF (metallic_roughness_bsdf.cpp) written for one SIMD lane of the
// path tracer's surface lanes (integrators/surface_lanes.h), in its commonest case: opaque,
// isotropic, rough and without iridescence, a GGX metal mixed with a GGX-coated Lambert. Every
// branch of the model is a select here, so that a loop over lanes vectorises, and every value
// is worked out with the model's operations in the model's order, so that each lane's results
// are the model's to the bit (tests/render/surface_lanes_test.cpp).
#pragma once

#include <algorithm>
#include <cmath>

#include "materials/bsdf_models.h"
#include "materials/fresnel.h"
#include "materials/metallic_roughness.h"
#include "materials/metallic_roughness_terms.h"
#include "materials/microfacet.h"
#include "materials/microfacet_energy.h"
#include "materials/shading_frame.h"
#include "math/lane.h"

namespace radiant {

// Whether a material's parameters are the case these lanes shade. Diffuse transmission
// (KHR_materials_diffuse_transmission) is left to the single path, as glass is: the lanes shade
// one hemisphere, and thin translucent surfaces are too rare to pay a second one in every lane.
inline bool is_metallic_roughness_lane_case(const MetallicRoughnessParams& p) {
  return !p.anisotropic && !p.smooth && !(p.glass > 0) && !(p.iridescence > 0) &&
         !(max_component(p.diffuse_transmitted) > 0);
}

// The parameters of the case that a lane reads (MetallicRoughnessParams' fields).
struct GlossyLaneMaterial {
  color3 base;
  float alpha, ior, ior_f0;
  float metal, plastic;
  float specular;  // the coating's strength and its tinted F0
  color3 specular_f0;
  MicrofacetEnergy energy;
};

// The lobes seen from wo (MetallicRoughnessLobes' fields), meaningful where `valid`.
struct GlossyLaneLobes {
  vec3 normal;  // the frame's z, make_shading_frame's input: the shading normal on wo's side
  vec3 wo;      // local
  float p_specular, p_diffuse;
  float coating_o, loss_o, lambda_o;
  bool valid;
};

// coating_rise and coating_fresnel without iridescence.
[[gnu::always_inline]] inline float glossy_coating_rise(const GlossyLaneMaterial& m, float cos) {
  return fresnel_rise(cos, m.ior, m.ior_f0);
}
// specular_fresnel without glass and iridescence, given the coating's curve at `cos_h`.
[[gnu::always_inline]] inline color3 glossy_specular_fresnel(const GlossyLaneMaterial& m, float cos_h, float rise) {
  color3 coating = tinted_coating_reflectance(m.specular_f0, rise) * m.specular;
  color3 plastic = lane::select(m.plastic > 0, coating * m.plastic, color3{0, 0, 0});
  color3 metal = lane::select(m.metal > 0, fresnel_schlick(m.base, cos_h) * m.metal, color3{0, 0, 0});
  float glass = 0;
  return metal + plastic + color3{glass, glass, glass};
}

// The lobes' frame (facing_frame) for `n` the shading normal (any side) and wo the unit
// direction towards the viewer: its z in `normal`, and wo in it.
[[gnu::always_inline]] inline vec3 glossy_lane_frame(vec3 n, vec3 wo, vec3& normal) {
  normal = dot(n, wo) < 0 ? -n : n;
  return to_local(make_shading_frame(normal), wo);
}

// make_metallic_roughness_lobes for `n` and `wo` as glossy_lane_frame's, given the tables'
// values `at_o` along wo (microfacet_albedos at its local z).
[[gnu::always_inline]] inline GlossyLaneLobes make_glossy_lane_lobes(const GlossyLaneMaterial& m, vec3 n, vec3 wo,
                                                                     MicrofacetAlbedos at_o) {
  GlossyLaneLobes l;
  l.wo = glossy_lane_frame(n, wo, l.normal);
  bool valid = (l.wo.z > 1e-7f) & lane::finite(l.wo);
  bool colored = max_component(m.base) > 0;
  float cos_o = l.wo.z;
  float rise_o = glossy_coating_rise(m, cos_o);
  l.loss_o = 1 - at_o.albedo;
  l.coating_o = coating_passage_of(m.energy, l.loss_o, at_o.rise);
  l.lambda_o = ggx_lambda(l.wo, m.alpha);
  bool specular_present = (m.metal > 0) | (m.plastic * m.specular > 0);
  float specular = selection_weight(specular_present, mean(glossy_specular_fresnel(m, cos_o, rise_o)), false);
  bool diffuse_present = ((m.plastic > 0) & colored) | (max_component(m.energy.multiple_scattering) > 0);
  float diffuse =
      selection_weight(diffuse_present, cosine_lobes_albedo(m.energy, m.base, m.plastic, l.coating_o, l.loss_o), false);
  float transmitted = 0;
  float total = specular + diffuse + transmitted;
  l.valid = valid & !(total <= 0);  // as the model's test: a NaN total leaves it valid
  l.p_specular = specular / total;
  l.p_diffuse = diffuse / total;
  return l;
}

// evaluate<true, WithPdf>: f(wo, wi) * |cos| at the local direction `wi`, given the tables'
// values `at_i` there (microfacet_albedos at wi.z), and the pdf that the lobes sample it with
// (0 where not finite). `in_range` turns false where the half vector's normalize() would have
// rescaled: the lane must fall back.
template <bool WithPdf>
[[gnu::always_inline]] inline color3 eval_glossy_lane(const GlossyLaneMaterial& m, const GlossyLaneLobes& l, vec3 wi,
                                                      MicrofacetAlbedos at_i, float& pdf, bool& in_range) {
  bool upper = l.valid & !(std::abs(wi.z) < 1e-7f) & (wi.z > 0);
  // The coated Lambert and the multiple scattering (wi.z is masked off below the surface).
  color3 diffuse = eval_cosine_lobes(m.energy, m.base, m.plastic, l.coating_o, l.loss_o, wi.z, at_i);
  color3 f = color3{0, 0, 0} + lane::select(upper & (l.p_diffuse > 0), diffuse, color3{0, 0, 0});
  pdf = 0;
  if constexpr (WithPdf) pdf = upper ? pdf + l.p_diffuse * wi.z * inv_pi : pdf;
  // The rough reflection (add_rough_reflection).
  bool h_in_range;
  vec3 h = lane::normalize_in_range(l.wo + wi, h_in_range);
  float cos_h = dot(l.wo, h);
  bool reflects = upper & (l.p_specular > 0) & !(cos_h <= 0);  // a NaN goes on, as in the model
  in_range = h_in_range | !(upper & (l.p_specular > 0));
  float density = ggx_distribution(h, m.alpha);
  float rise = m.plastic > 0 ? glossy_coating_rise(m, cos_h) : 0.0f;
  float masking_shadowing = ggx_masking_shadowing_of(l.lambda_o, ggx_lambda(wi, m.alpha));
  color3 reflected = glossy_specular_fresnel(m, cos_h, rise) * (density * masking_shadowing / (4 * l.wo.z));
  f = lane::select(reflects, f + reflected, f);
  if constexpr (WithPdf) {
    float visible = ggx_visible_density(l.wo, h, l.lambda_o, density);
    pdf = reflects ? pdf + l.p_specular * (visible / (4 * cos_h)) : pdf;
    pdf = lane::zero_unless(lane::finite(pdf), pdf);
  }
  bool finite = lane::finite(f);
  return {lane::zero_unless(finite, f.x), lane::zero_unless(finite, f.y), lane::zero_unless(finite, f.z)};
}

}  // namespace radiant
