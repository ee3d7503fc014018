// Directional albedo of single-scattering GGX reflection, tabulated once per process, for the
// energy compensation of the metallic-roughness lobes (Kulla and Conty 2017): what one
// reflection misses is given back by a multiple-scattering lobe, and a layer below a dielectric
// coating receives what the coating does not reflect. Lookups are bilinear (trilinear with the
// ior) and branch-free, so the scalar BSDF and its SIMD lanes share them to the bit.
#pragma once

#include <algorithm>

namespace radiant {

// Table coordinates: cosθ and GGX roughness sqrt(α) on [0, 1], and the coating's ior as
// t = (ior − 1)/(ior + 1) on [0, albedo_ior_max] (ior 1 to 9; 1.5 is the node t = 0.2).
constexpr int albedo_cosines = 32, albedo_roughnesses = 32, albedo_iors = 9;
constexpr float albedo_ior_max = 0.8f;

struct MicrofacetAlbedoTables {
  // E(cosθ, r): the GGX reflection's albedo with Fresnel 1, [roughness][cosine].
  float ggx[albedo_roughnesses][albedo_cosines];
  // 2∫E(μ)μ dμ of the interpolated rows: the albedo under uniform incident light.
  float ggx_average[albedo_roughnesses];
  // The albedo with Fresnel = the coating's rescaled curve (F − F0)/(1 − F0) of the ior at
  // the microfacet cosine, [ior][roughness][cosine], and its cosine-weighted average.
  float rise[albedo_iors][albedo_roughnesses][albedo_cosines];
  float rise_average[albedo_iors][albedo_roughnesses];
  // 2∫((F(μ) − F0)/(1 − F0))μ dμ: the rescaled curve's hemispherical average, per ior node.
  float fresnel_rise_average[albedo_iors];
};

// Integrated on first use by a fixed midpoint rule over visible normals (~20 ms); every material
// asks for it when it is made, so lookups need no guard.
const MicrofacetAlbedoTables& microfacet_albedo_tables();
// Its storage, which the lookups read at a constant address: no pointer per material and lane.
extern MicrofacetAlbedoTables microfacet_albedo_storage;

// The table coordinate of a GGX alpha (sqrt, clamped), and of a coating's ior.
float albedo_roughness_coordinate(float alpha);
float albedo_ior_coordinate(float ior);

namespace albedo_detail {
// The cell below `x` on a grid of `n` nodes over [0, `extent`] and the fraction into it; NaN
// gives cell 0, so that a masked-off lane never reads outside the table.
[[gnu::always_inline]] inline int cell(float x, int n, float extent, float& fraction) {
  float scaled = std::min(std::max(0.0f, x), extent) * (float(n - 1) / extent);
  int index = std::min(int(scaled), n - 2);
  fraction = scaled - float(index);
  return index;
}
[[gnu::always_inline]] inline float lerp1(float a, float b, float t) { return a + (b - a) * t; }
}  // namespace albedo_detail

// E(cosθ, r), bilinear.
[[gnu::always_inline]] inline float ggx_albedo(float cos, float roughness) {
  using namespace albedo_detail;
  float fx, fy;
  int x = cell(cos, albedo_cosines, 1, fx), y = cell(roughness, albedo_roughnesses, 1, fy);
  const auto& e = microfacet_albedo_storage.ggx;
  return lerp1(lerp1(e[y][x], e[y][x + 1], fx), lerp1(e[y + 1][x], e[y + 1][x + 1], fx), fy);
}
[[gnu::always_inline]] inline float ggx_albedo_average(float roughness) {
  using namespace albedo_detail;
  float fy;
  int y = cell(roughness, albedo_roughnesses, 1, fy);
  const auto& e = microfacet_albedo_storage.ggx_average;
  return lerp1(e[y], e[y + 1], fy);
}
// The albedo weighted by the coating's rescaled Fresnel curve, trilinear.
[[gnu::always_inline]] inline float ggx_rise_albedo(float cos, float roughness, float ior_coordinate) {
  using namespace albedo_detail;
  float fx, fy, fz;
  int x = cell(cos, albedo_cosines, 1, fx), y = cell(roughness, albedo_roughnesses, 1, fy);
  int z = cell(ior_coordinate, albedo_iors, albedo_ior_max, fz);
  const auto& r = microfacet_albedo_storage.rise;
  float near = lerp1(lerp1(r[z][y][x], r[z][y][x + 1], fx), lerp1(r[z][y + 1][x], r[z][y + 1][x + 1], fx), fy);
  float far = lerp1(lerp1(r[z + 1][y][x], r[z + 1][y][x + 1], fx), lerp1(r[z + 1][y + 1][x], r[z + 1][y + 1][x + 1], fx), fy);
  return lerp1(near, far, fz);
}
float ggx_rise_albedo_average(float roughness, float ior_coordinate);
float fresnel_rise_average(float ior_coordinate);

}  // namespace radiant
