#include "lights/light_bounds.h"

#include <algorithm>
#include <cmath>

namespace radiant {

namespace {

using importance_detail::safe_sqrt;

float safe_acos(float x) { return std::acos(std::clamp(x, -1.0f, 1.0f)); }

// `v` rotated by `angle` about unit `axis` (Rodrigues).
vec3 rotate(vec3 v, vec3 axis, float angle) {
  float c = std::cos(angle), s = std::sin(angle);
  return v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1 - c));
}

// The smallest cone (axis, cos of its half-angle) holding two cones (pbrt-v4's DirectionCone Union).
void merge_cones(vec3 axis_a, float cos_a, vec3 axis_b, float cos_b, vec3& axis, float& cos_spread) {
  float theta_a = safe_acos(cos_a), theta_b = safe_acos(cos_b);
  float theta_d = safe_acos(dot(axis_a, axis_b));
  if (std::min(theta_d + theta_b, pi) <= theta_a) {
    axis = axis_a, cos_spread = cos_a;
    return;
  }
  if (std::min(theta_d + theta_a, pi) <= theta_b) {
    axis = axis_b, cos_spread = cos_b;
    return;
  }
  float theta_o = (theta_a + theta_d + theta_b) / 2;
  vec3 rotation_axis = cross(axis_a, axis_b);
  if (theta_o >= pi || length_squared(rotation_axis) == 0) {
    axis = axis_a, cos_spread = -1;  // the whole sphere
    return;
  }
  axis = normalize(rotate(axis_a, normalize(rotation_axis), theta_o - theta_a));
  cos_spread = std::cos(theta_o);
}

}  // namespace

LightBounds point_light_bounds(vec3 position, vec3 axis, float cos_spread, float cos_falloff, float intensity) {
  LightBounds b;
  b.lower = b.upper = position;
  b.axis = axis;
  b.cos_spread = cos_spread;
  b.cos_falloff = cos_falloff;
  b.intensity = intensity;
  return b;
}

LightBounds merge(const LightBounds& a, const LightBounds& b) {
  if (!(a.intensity > 0)) return b;
  if (!(b.intensity > 0)) return a;
  LightBounds m;
  m.lower = min(a.lower, b.lower);
  m.upper = max(a.upper, b.upper);
  merge_cones(a.axis, a.cos_spread, b.axis, b.cos_spread, m.axis, m.cos_spread);
  m.cos_falloff = std::min(a.cos_falloff, b.cos_falloff);
  m.intensity = a.intensity + b.intensity;
  m.two_sided = a.two_sided || b.two_sided;
  return m;
}

ImportanceBounds importance_bounds(const LightBounds& bounds) {
  ImportanceBounds b;
  b.center = (bounds.lower + bounds.upper) * 0.5f;
  b.radius2 = length_squared(bounds.upper - bounds.lower) * 0.25f;
  b.radius = std::sqrt(b.radius2);
  b.axis = bounds.axis;
  b.cos_spread = bounds.cos_spread;
  b.sin_spread = safe_sqrt(1 - bounds.cos_spread * bounds.cos_spread);
  b.cos_falloff = bounds.cos_falloff;
  b.intensity = bounds.intensity;
  b.two_sided = bounds.two_sided;
  return b;
}

float orientation_measure(const LightBounds& bounds) {
  float theta_o = safe_acos(bounds.cos_spread), theta_e = safe_acos(bounds.cos_falloff);
  float theta_w = std::min(theta_o + theta_e, pi);
  float sin_o = safe_sqrt(1 - bounds.cos_spread * bounds.cos_spread);
  return 2 * pi * (1 - bounds.cos_spread) +
         pi / 2 * (2 * theta_w * sin_o - std::cos(theta_o - 2 * theta_w) - 2 * theta_o * sin_o + bounds.cos_spread);
}

}  // namespace radiant
