// The GGX albedo tables of microfacet_albedo.h, integrated on first use.
#include "materials/microfacet_albedo.h"

#include <cmath>

#include "materials/fresnel.h"
#include "materials/metallic_roughness.h"
#include "materials/microfacet.h"

namespace radiant {

namespace {

// Visible normals on a midpoint grid, radially in s with u = 1 − (1 − s)³: the light a smooth
// lobe loses is in the distribution's tail, u near 1. Within 0.0015 of a 1024-step grid.
constexpr int radial_steps = 32, azimuth_steps = 8;

float cosine_node(int i) { return std::max(float(i) / (albedo_cosines - 1), 1e-4f); }
float roughness_node(int i) { return float(i) / (albedo_roughnesses - 1); }
float ior_node_coordinate(int i) { return albedo_ior_max * float(i) / (albedo_iors - 1); }
float ior_of_coordinate(float t) { return (1 + t) / (1 - t); }

// One cell of the tables: E and the rise-weighted E for every ior, at one cosine and roughness.
void integrate_cell(float cos_o, float alpha, MicrofacetAlbedoTables& t, int y, int x) {
  vec3 wo = {std::sqrt(1 - cos_o * cos_o), 0, cos_o};
  float lambda_o = ggx_lambda(wo, alpha);
  double e = 0, rise[albedo_iors] = {}, total = 0;
  for (int i = 0; i < radial_steps; ++i)
    for (int j = 0; j < azimuth_steps; ++j) {
      double s = (i + 0.5) / radial_steps, jacobian = 3 * (1 - s) * (1 - s);
      float u = float(1 - (1 - s) * (1 - s) * (1 - s));
      total += jacobian;
      vec3 h = sample_ggx_visible_normal(wo, alpha, {u, (j + 0.5f) / azimuth_steps});
      vec3 wi = reflect(wo, h);
      if (wi.z <= 0) continue;
      // f·cosθi over the visible-normal density is G2/G1 (height-correlated Smith).
      double weight = jacobian * (1 + lambda_o) / (1 + lambda_o + ggx_lambda(wi, alpha));
      float cos_h = dot(wo, h);
      e += weight;
      for (int z = 0; z < albedo_iors; ++z) {
        float ior = ior_of_coordinate(ior_node_coordinate(z));
        rise[z] += weight * fresnel_rise(cos_h, ior, dielectric_f0(ior));
      }
    }
  // Over the rule's own total weight, so that a mirror (alpha 0) reflects exactly 1.
  t.ggx[y][x] = float(e / total);
  for (int z = 0; z < albedo_iors; ++z) t.rise[z][y][x] = float(rise[z] / total);
}

// 2∫f(μ)μ dμ of the piecewise-linear interpolation of a row, exactly.
float cosine_weighted_average(const float (&row)[albedo_cosines]) {
  double sum = 0, h = 1.0 / (albedo_cosines - 1);
  for (int i = 0; i + 1 < albedo_cosines; ++i) {
    double a = i * h, b = (i + 1) * h;
    sum += h * (row[i] * (2 * a + b) + row[i + 1] * (a + 2 * b)) / 6;
  }
  return float(2 * sum);
}

MicrofacetAlbedoTables integrate_tables() {
  MicrofacetAlbedoTables t{};
  for (int y = 0; y < albedo_roughnesses; ++y) {
    float r = roughness_node(y);
    for (int x = 0; x < albedo_cosines; ++x) integrate_cell(cosine_node(x), r * r, t, y, x);
    t.ggx_average[y] = cosine_weighted_average(t.ggx[y]);
    for (int z = 0; z < albedo_iors; ++z) t.rise_average[z][y] = cosine_weighted_average(t.rise[z][y]);
  }
  constexpr int cosine_steps = 4096;
  for (int z = 0; z < albedo_iors; ++z) {
    float ior = ior_of_coordinate(ior_node_coordinate(z));
    double sum = 0;
    for (int i = 0; i < cosine_steps; ++i) {
      float mu = (i + 0.5f) / cosine_steps;
      sum += fresnel_rise(mu, ior, dielectric_f0(ior)) * mu;
    }
    t.fresnel_rise_average[z] = float(2 * sum / cosine_steps);
  }
  return t;
}

}  // namespace

MicrofacetAlbedoTables microfacet_albedo_storage;

const MicrofacetAlbedoTables& microfacet_albedo_tables() {
  static const bool integrated = (microfacet_albedo_storage = integrate_tables(), true);
  (void)integrated;
  return microfacet_albedo_storage;
}

float albedo_roughness_coordinate(float alpha) { return std::sqrt(std::clamp(alpha, 0.0f, 1.0f)); }

float albedo_ior_coordinate(float ior) { return std::clamp(std::abs(ior - 1) / (ior + 1), 0.0f, albedo_ior_max); }

float ggx_rise_albedo_average(float roughness, float ior_coordinate) {
  using namespace albedo_detail;
  float fy, fz;
  int y = cell(roughness, albedo_roughnesses, 1, fy), z = cell(ior_coordinate, albedo_iors, albedo_ior_max, fz);
  const auto& r = microfacet_albedo_storage.rise_average;
  return lerp1(lerp1(r[z][y], r[z][y + 1], fy), lerp1(r[z + 1][y], r[z + 1][y + 1], fy), fz);
}

float fresnel_rise_average(float ior_coordinate) {
  using namespace albedo_detail;
  float fz;
  int z = cell(ior_coordinate, albedo_iors, albedo_ior_max, fz);
  const auto& f = microfacet_albedo_storage.fresnel_rise_average;
  return lerp1(f[z], f[z + 1], fz);
}

}  // namespace radiant
