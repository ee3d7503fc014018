// Charlie sheen: D(h) = (2 + 1/a) sin(θh)^(1/a) / 2π with a = roughness², over Ashikhmin's
// visibility 1 / (4 (cosθi + cosθo − cosθi cosθo)).
#include "materials/sheen.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace radiant {

namespace {

// The sharpest distribution: a below this (roughness 0.1) is taken as this, since a → 0 diverges
// and the albedo table cannot resolve it.
constexpr float min_sheen_alpha = 1e-2f;

float charlie_distribution(float cos_h, float alpha) {
  float inv_alpha = 1 / std::max(alpha, min_sheen_alpha);
  float sin2 = std::max(0.0f, 1 - cos_h * cos_h);
  return (2 + inv_alpha) * std::pow(sin2, 0.5f * inv_alpha) / (2 * pi);
}

constexpr int table_size = 32;  // sqrt(cos θ) and roughness, each on [0, 1]
using AlbedoTable = std::array<float, table_size * table_size>;

// E(cosθo) = ∫ eval_sheen dωi by the midpoint rule in (sqrt(cosθi), φ): the lobe and Ashikhmin's
// visibility grow towards grazing angles, where the square-root steps crowd.
AlbedoTable integrate_albedo_table() {
  AlbedoTable table{};
  constexpr int steps = 96;
  for (int r = 0; r < table_size; ++r)
    for (int c = 0; c < table_size; ++c) {
      float roughness = float(r) / (table_size - 1), root_o = float(c) / (table_size - 1);
      float cos_o = std::max(root_o * root_o, 1e-4f);
      vec3 wo = {std::sqrt(1 - cos_o * cos_o), 0, cos_o};
      double sum = 0;
      for (int i = 0; i < steps; ++i)
        for (int j = 0; j < steps; ++j) {
          float root_i = (i + 0.5f) / steps, phi = 2 * pi * (j + 0.5f) / steps;
          float cos_i = root_i * root_i, sin_i = std::sqrt(1 - cos_i * cos_i);
          // dω = dcosθ dφ = 2 sqrt(cosθ) d(sqrt(cosθ)) dφ; eval_sheen carries cosθi already.
          sum += 2 * root_i * eval_sheen(wo, {sin_i * std::cos(phi), sin_i * std::sin(phi), cos_i}, roughness);
        }
      table[size_t(r * table_size + c)] = float(std::min(1.0, sum * 2 * pi / (steps * steps)));
    }
  return table;
}

}  // namespace

float eval_sheen(vec3 wo, vec3 wi, float sheen_roughness) {
  if (wo.z <= 0 || wi.z <= 0) return 0;
  vec3 h = normalize(wo + wi);
  float r = std::clamp(sheen_roughness, 0.0f, 1.0f);
  float visibility = 1 / (4 * (wi.z + wo.z - wi.z * wo.z));
  return charlie_distribution(h.z, r * r) * visibility * wi.z;
}

float sheen_albedo(float cos_theta, float sheen_roughness) {
  static const AlbedoTable table = integrate_albedo_table();
  float x = std::sqrt(std::clamp(cos_theta, 0.0f, 1.0f)) * (table_size - 1);
  float y = std::clamp(sheen_roughness, 0.0f, 1.0f) * (table_size - 1);
  int x0 = std::min(int(x), table_size - 2), y0 = std::min(int(y), table_size - 2);
  float fx = x - float(x0), fy = y - float(y0);
  auto at = [&](int xi, int yi) { return table[size_t(yi * table_size + xi)]; };
  float low = at(x0, y0) + (at(x0 + 1, y0) - at(x0, y0)) * fx;
  float high = at(x0, y0 + 1) + (at(x0 + 1, y0 + 1) - at(x0, y0 + 1)) * fx;
  return low + (high - low) * fy;
}

}  // namespace radiant
