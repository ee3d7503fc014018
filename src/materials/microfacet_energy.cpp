// The per-material weights of the energy compensation (microfacet_energy.h).
#include "materials/microfacet_energy.h"

#include <algorithm>
#include <cmath>

namespace radiant {

namespace {

// Kulla and Conty's Fresnel of the multiple-scattering lobe: what keeps bouncing between
// microfacets, each bounce reflecting the hemispherical average F_avg, relative to F = 1.
color3 multiple_scattering_fresnel(color3 f_avg, float e_avg) {
  color3 inner = color3{1, 1, 1} - f_avg * (1 - e_avg);
  return f_avg * f_avg * e_avg / inner;
}

// Above this the products' normalisations are infinite: no lobe (a mirror, a white mirror coating).
constexpr float min_escape = 1e-6f;

}  // namespace

MicrofacetEnergy make_microfacet_energy(float alpha, bool smooth, float ior, float metal, color3 metal_f0, float plastic,
                                        float specular, color3 specular_f0) {
  MicrofacetEnergy e;
  microfacet_albedo_tables();  // integrated once, before any lookup
  e.roughness = smooth ? 0 : albedo_roughness_coordinate(alpha);
  e.ior = albedo_ior_coordinate(ior);
  float e_avg = ggx_albedo_average(e.roughness);
  // Schlick's curve averages to F0 + (1 − F0)/21 over the cosine-weighted hemisphere.
  color3 metal_avg = metal_f0 + (color3{1, 1, 1} - metal_f0) * (1.0f / 21);
  float rise_avg = fresnel_rise_average(e.ior);
  color3 coating_avg = (specular_f0 + (color3{1, 1, 1} - specular_f0) * rise_avg) * specular;
  if (!smooth && 1 - e_avg > min_escape) {
    e.multiple_scattering = multiple_scattering_fresnel(metal_avg, e_avg) * metal +
                            multiple_scattering_fresnel(coating_avg, e_avg) * plastic;
    e.multiple_normalization = 1 / (pi * (1 - e_avg));
  }
  float f0_max = max_component(specular_f0);
  e.coating_reflect = specular * f0_max;
  e.coating_rise = specular * (1 - f0_max);
  e.coating_multiple = smooth ? 0 : max_component(multiple_scattering_fresnel(coating_avg, e_avg));
  float coating_avg_albedo = e.coating_reflect * e_avg + e.coating_rise * ggx_rise_albedo_average(e.roughness, e.ior) +
                             e.coating_multiple * (1 - e_avg);
  e.diffuse_normalization = 1 - coating_avg_albedo > min_escape ? 1 / (1 - coating_avg_albedo) : 0;
  return e;
}

}  // namespace radiant
