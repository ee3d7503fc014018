// Energy compensation of the metallic-roughness lobes, as Cycles and OpenPBR do it (Kulla and
// Conty 2017): a multiple-scattering lobe gives back what single-scattering GGX loses, and the
// diffuse under the dielectric coating receives what the coating does not reflect. Both are
// reciprocal products f(μo)·f(μi), normalised so that a white surface reflects exactly 1.
// Shared by the scalar model and its SIMD lanes (metallic_roughness_lane.h), to the bit.
#pragma once

#include "materials/microfacet_albedo.h"
#include "math/vec.h"

namespace radiant {

// The per-material part: table coordinates and the products' weights.
struct MicrofacetEnergy {
  float roughness = 0;  // table coordinate of the lobes' (effective) alpha
  float ior = 0.2f;     // table coordinate of the coating's ior
  // The multiple-scattering lobe, f·cosθi = colour · (1 − E(μo))(1 − E(μi)) · normalization · μi:
  // the metal's and the coating's F_ms by their mix shares, and 1/(π(1 − E_avg)).
  color3 multiple_scattering;
  float multiple_normalization = 0;
  // The coating's albedo along μ (brightest channel) is reflect·E(μ) + rise·R(μ) + multiple·(1 − E(μ)),
  // R the albedo under its rescaled Fresnel curve; the diffuse below it is scaled by
  // (1 − E_s(μo))(1 − E_s(μi)) / (1 − E_s_avg).
  float coating_reflect = 0, coating_rise = 0, coating_multiple = 0;
  float diffuse_normalization = 1;
};

// `alpha` is the lobes' GGX alpha (sqrt(αx·αy) when anisotropic, 0 when smooth); the coating is
// KHR_materials_specular's: strength `specular`, tinted F0 `specular_f0` of `ior`.
MicrofacetEnergy make_microfacet_energy(float alpha, bool smooth, float ior, float metal, color3 metal_f0, float plastic,
                                        float specular, color3 specular_f0);

// The tables' values along a direction of cosine μ: E(μ) and R(μ), looked up once so that a
// loop over SIMD lanes can take them from arrays (its table reads would not vectorise).
struct MicrofacetAlbedos {
  float albedo, rise;
};
[[gnu::always_inline]] inline MicrofacetAlbedos microfacet_albedos(const MicrofacetEnergy& e, float cos) {
  return {ggx_albedo(cos, e.roughness), ggx_rise_albedo(cos, e.roughness, e.ior)};
}

// 1 − E(μ): what single scattering loses along a direction of cosine `cos`.
[[gnu::always_inline]] inline float ggx_energy_loss(const MicrofacetEnergy& e, float cos) {
  return 1 - ggx_albedo(cos, e.roughness);
}

// 1 − E_s(μ): what the coating lets through, given `loss` = ggx_energy_loss and `rise` = R(μ).
[[gnu::always_inline]] inline float coating_passage_of(const MicrofacetEnergy& e, float loss, float rise) {
  return 1 - (e.coating_reflect * (1 - loss) + e.coating_rise * rise + e.coating_multiple * loss);
}
// The same along `cos`.
[[gnu::always_inline]] inline float coating_passage(const MicrofacetEnergy& e, float cos, float loss) {
  return coating_passage_of(e, loss, ggx_rise_albedo(cos, e.roughness, e.ior));
}

// f·|cosθi| of the coated Lambertian of albedo `color` × its share `plastic`, at |cos_i| > 0 with
// the tables' values `at_i` there; `passage_o` is along wo. The coating lets light through both
// ways, whichever side wi leaves (KHR_materials_diffuse_transmission's lobe uses it below).
[[gnu::always_inline]] inline color3 eval_coated_diffuse(const MicrofacetEnergy& e, color3 color, float plastic,
                                                         float passage_o, float cos_i, MicrofacetAlbedos at_i) {
  float passage = passage_o * coating_passage_of(e, 1 - at_i.albedo, at_i.rise) * e.diffuse_normalization;
  return color * (plastic * passage * inv_pi * cos_i);
}

// f·cosθi of the lobes the cosine hemisphere samples, the plastic's diffuse (`diffuse` × its share
// `plastic`) and the multiple scattering, at cos_i > 0 with the tables' values `at_i` there;
// `passage_o` and `loss_o` are along wo.
[[gnu::always_inline]] inline color3 eval_cosine_lobes(const MicrofacetEnergy& e, color3 diffuse, float plastic,
                                                       float passage_o, float loss_o, float cos_i,
                                                       MicrofacetAlbedos at_i) {
  float loss = 1 - at_i.albedo;
  return eval_coated_diffuse(e, diffuse, plastic, passage_o, cos_i, at_i) +
         e.multiple_scattering * (loss_o * loss * e.multiple_normalization * cos_i);
}
// The same, looking the tables up.
[[gnu::always_inline]] inline color3 eval_cosine_lobes(const MicrofacetEnergy& e, color3 diffuse, float plastic,
                                                       float passage_o, float loss_o, float cos_i) {
  return eval_cosine_lobes(e, diffuse, plastic, passage_o, loss_o, cos_i, microfacet_albedos(e, cos_i));
}

// Their mean albedo along wo (lobe selection): exactly (1 − E_s(μo))·share·diffuse + F_ms·(1 − E(μo)).
[[gnu::always_inline]] inline float cosine_lobes_albedo(const MicrofacetEnergy& e, color3 diffuse, float plastic,
                                                        float passage_o, float loss_o) {
  return plastic * mean(diffuse) * passage_o + mean(e.multiple_scattering) * loss_o;
}

}  // namespace radiant
