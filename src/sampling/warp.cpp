#include "sampling/warp.h"

#include "sampling/cosine_warp.h"

#include <algorithm>
#include <cmath>

namespace radiant {

vec3 sample_cosine_hemisphere(vec2 u) { return cosine_hemisphere(u.x, u.y); }

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
