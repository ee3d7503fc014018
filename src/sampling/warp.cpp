#include "sampling/warp.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace radiant {

namespace {

// sin and cos of |theta| <= pi/4 by their Taylor series, truncated where the next term falls
// below float precision (theta^11/11! < 2e-9, theta^10/10! < 3e-8). The libm call and its range
// reduction cost more than the rest of a cosine-weighted sample.
void sin_cos_quarter(float theta, float& s, float& c) {
  float t2 = theta * theta;
  s = theta * (1 + t2 * (-1.0f / 6 + t2 * (1.0f / 120 + t2 * (-1.0f / 5040 + t2 * (1.0f / 362880)))));
  c = 1 + t2 * (-0.5f + t2 * (1.0f / 24 + t2 * (-1.0f / 720 + t2 * (1.0f / 40320))));
}

}  // namespace

vec3 sample_cosine_hemisphere(vec2 u) {
  // Concentric disk mapping (Shirley-Chiu), lifted to the hemisphere. The angle within the
  // major axis's wedge is theta = (pi/4) * minor/major; on the b-major wedges phi = pi/2 - theta,
  // which swaps sine and cosine. One division, no trigonometric call, and no branch on the
  // wedge: which axis is major is a coin flip no branch predictor can learn.
  float a = 2 * u.x - 1, b = 2 * u.y - 1;
  if (a == 0 && b == 0) return {0, 0, 1};
  // A bit mask, not a float 0/1 or a ternary: GCC turns both of those back into a branch.
  uint32_t a_major = 0u - uint32_t(std::abs(a) > std::abs(b));
  auto pick = [a_major](float if_a_major, float otherwise) {
    return std::bit_cast<float>((std::bit_cast<uint32_t>(if_a_major) & a_major) |
                                (std::bit_cast<uint32_t>(otherwise) & ~a_major));
  };
  float r = pick(a, b);
  float s, c;
  sin_cos_quarter((pi / 4) * (pick(b, a) / r), s, c);
  float x = r * pick(c, s), y = r * pick(s, c);
  return {x, y, std::sqrt(std::max(0.0f, 1 - r * r))};
}

vec3 sample_uniform_sphere(vec2 u) {
  float z = 1 - 2 * u.x;
  float r = std::sqrt(std::max(0.0f, 1 - z * z));
  float phi = 2 * pi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

vec3 sample_uniform_cone(vec2 u, float cos_max) {
  float cos_theta = (1 - u.x) + u.x * cos_max;
  float sin_theta = std::sqrt(std::max(0.0f, 1 - cos_theta * cos_theta));
  float phi = 2 * pi * u.y;
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

vec2 sample_uniform_triangle(vec2 u) {
  // Heitz 2019's low-distortion mapping.
  float b0, b1;
  if (u.x < u.y) {
    b0 = u.x / 2;
    b1 = u.y - b0;
  } else {
    b1 = u.y / 2;
    b0 = u.x - b1;
  }
  return {b0, b1};
}

vec2 sample_uniform_disk(vec2 u) {
  vec3 d = sample_cosine_hemisphere(u);  // the cosine-weighted hemisphere is the disk, lifted
  return {d.x, d.y};
}

vec2 sample_regular_polygon(vec2 u, int corners) {
  // u.x picks one of the triangles (centre, corner k, corner k+1) and, rescaled, places the point in it.
  float scaled = u.x * float(corners);
  int k = std::min(int(scaled), corners - 1);
  vec2 b = sample_uniform_triangle({scaled - float(k), u.y});
  float step = 2 * pi / float(corners), a0 = pi / 2 + step * float(k), a1 = a0 + step;
  return vec2{std::cos(a0), std::sin(a0)} * b.x + vec2{std::cos(a1), std::sin(a1)} * b.y;
}

vec3 to_world(vec3 n, vec3 d) {
  vec3 t, b;
  orthonormal_basis(n, t, b);
  return t * d.x + b * d.y + n * d.z;
}

}  // namespace radiant
