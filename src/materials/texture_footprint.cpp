#include "materials/texture_footprint.h"

#include <cmath>

namespace radiant {

namespace {

// Where the ray (origin, direction) meets the plane through p with normal n, minus p; zero
// when it runs along the plane (pbrt's choice: no footprint rather than an infinite one).
vec3 offset_on_plane(vec3 origin, vec3 direction, vec3 p, vec3 n) {
  float t = dot(n, p - origin) / dot(n, direction);
  vec3 offset = origin + direction * t - p;
  return is_finite(offset) ? offset : vec3{0, 0, 0};
}

}  // namespace

void approximate_dp_dxy(const PixelSpread& s, vec3 p, vec3 n, vec3& dpdx, vec3& dpdy) {
  // The camera ray through p, and two axes across it that follow the image's.
  vec3 along = s.parallel ? s.forward : normalize(p - s.camera_position);
  vec3 origin = s.parallel ? p - s.forward * dot(p - s.camera_position, s.forward) : s.camera_position;
  vec3 x = s.right - along * dot(s.right, along);
  if (!(length_squared(x) > 1e-12f)) x = s.up - along * dot(s.up, along);
  x = normalize(x);
  vec3 y = cross(along, x);
  dpdx = offset_on_plane(origin + x * s.origin_step_x, along + x * s.direction_step_x, p, n);
  dpdy = offset_on_plane(origin + y * s.origin_step_y, along + y * s.direction_step_y, p, n);
}

}  // namespace radiant
