#include "sampling/warp.h"

#include <cmath>

namespace radiant {

vec3 sample_cosine_hemisphere(vec2 u) {
  // Concentric disk mapping (Shirley–Chiu), lifted to the hemisphere.
  float a = 2 * u.x - 1, b = 2 * u.y - 1;
  float r, phi;
  if (a == 0 && b == 0) return {0, 0, 1};
  if (std::abs(a) > std::abs(b)) {
    r = a;
    phi = (pi / 4) * (b / a);
  } else {
    r = b;
    phi = (pi / 2) - (pi / 4) * (a / b);
  }
  float x = r * std::cos(phi), y = r * std::sin(phi);
  return {x, y, std::sqrt(std::max(0.0f, 1 - x * x - y * y))};
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

vec3 to_world(vec3 n, vec3 d) {
  vec3 t, b;
  orthonormal_basis(n, t, b);
  return t * d.x + b * d.y + n * d.z;
}

}  // namespace radiant
