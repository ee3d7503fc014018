#include "lights/light_bounds.h"

#include <algorithm>
#include <cmath>

namespace radiant {

namespace {

float safe_sqrt(float x) { return std::sqrt(std::max(0.0f, x)); }
float safe_acos(float x) { return std::acos(std::clamp(x, -1.0f, 1.0f)); }

// cos(max(0, a - b)) from the sines and cosines of angles a and b in [0, pi].
float cos_of_difference_clamped(float sin_a, float cos_a, float sin_b, float cos_b) {
  if (cos_a > cos_b) return 1;
  return cos_a * cos_b + sin_a * sin_b;
}
// sin(max(0, a - b)) likewise.
float sin_of_difference_clamped(float sin_a, float cos_a, float sin_b, float cos_b) {
  if (cos_a > cos_b) return 0;
  return sin_a * cos_b - cos_a * sin_b;
}

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

float importance(const LightBounds& bounds, vec3 p, vec3 n) {
  if (!(bounds.intensity > 0)) return 0;
  vec3 center = (bounds.lower + bounds.upper) * 0.5f;
  float radius2 = length_squared(bounds.upper - bounds.lower) * 0.25f;  // of the box's bounding sphere
  vec3 to_point = p - center;
  float distance2 = length_squared(to_point);
  // Inside the bounding sphere every direction and cosine is possible: only the distance, clamped
  // to the sphere's radius, tells groups apart.
  if (distance2 <= radius2) return bounds.intensity / std::max(radius2, 1e-30f);

  vec3 wi = to_point / std::sqrt(distance2);  // from the group towards p
  float cos_w = dot(bounds.axis, wi);
  if (bounds.two_sided) cos_w = std::abs(cos_w);
  float sin_w = safe_sqrt(1 - cos_w * cos_w);
  // theta_b: the half-angle the bounding sphere subtends at p.
  float sin2_b = radius2 / distance2;
  float sin_b = std::sqrt(sin2_b), cos_b = safe_sqrt(1 - sin2_b);
  // theta': the smallest angle between an emitting normal and the direction to p.
  float sin_o = safe_sqrt(1 - bounds.cos_spread * bounds.cos_spread);
  float cos_x = cos_of_difference_clamped(sin_w, cos_w, sin_o, bounds.cos_spread);
  float sin_x = sin_of_difference_clamped(sin_w, cos_w, sin_o, bounds.cos_spread);
  float cos_emitter = cos_of_difference_clamped(sin_x, cos_x, sin_b, cos_b);
  if (cos_emitter <= bounds.cos_falloff) return 0;

  float estimate = bounds.intensity * cos_emitter / std::max(distance2, 1e-30f);
  if (!(n.x == 0 && n.y == 0 && n.z == 0)) {
    // Either side of the surface: a BSDF may transmit.
    float cos_i = std::abs(dot(wi, n));
    float sin_i = safe_sqrt(1 - cos_i * cos_i);
    estimate *= cos_of_difference_clamped(sin_i, cos_i, sin_b, cos_b);
  }
  return std::max(estimate, 0.0f);
}

float orientation_measure(const LightBounds& bounds) {
  float theta_o = safe_acos(bounds.cos_spread), theta_e = safe_acos(bounds.cos_falloff);
  float theta_w = std::min(theta_o + theta_e, pi);
  float sin_o = safe_sqrt(1 - bounds.cos_spread * bounds.cos_spread);
  return 2 * pi * (1 - bounds.cos_spread) +
         pi / 2 * (2 * theta_w * sin_o - std::cos(theta_o - 2 * theta_w) - 2 * theta_o * sin_o + bounds.cos_spread);
}

}  // namespace radiant
