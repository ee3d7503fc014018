// What the light BVH knows of a group of lights: where they are, which way they emit and how
// bright they are, and from that an estimate of how much they light a given point (pbrt-v4's
// LightBounds, after Conty Estevez and Kulla's many-light cones).
#pragma once

#include <algorithm>
#include <cmath>

#include "math/vec.h"

namespace radiant {

struct LightBounds {
  vec3 lower, upper;         // box around every emitting point
  vec3 axis = {0, 0, 1};     // unit centre of the cone of emitting normals
  float cos_spread = 1;      // cos theta_o: every emitting normal lies within theta_o of `axis`
  float cos_falloff = 0;     // cos theta_e: how far past its normal a point still emits (pi/2: Lambertian)
  float intensity = 0;       // radiant intensity along the normal, up to a common factor; 0 = emits nothing
  bool two_sided = false;    // emits along -normal too
};

// Bounds of a point emitting `intensity` within `cos_falloff` of `axis` (all directions: -1).
LightBounds point_light_bounds(vec3 position, vec3 axis, float cos_spread, float cos_falloff, float intensity);

// Bounds covering both (a group of lights); a side of intensity 0 is ignored.
LightBounds merge(const LightBounds& a, const LightBounds& b);

// A group's bounds as importance() reads them: what every evaluation would otherwise work out
// again from LightBounds (the centre, the bounding sphere, the sine of the cone of normals),
// worked out once per group when the light BVH is built.
struct ImportanceBounds {
  vec3 center;
  float radius = 0, radius2 = 0;  // of the box's bounding sphere, and its square
  vec3 axis = {0, 0, 1};
  float cos_spread = 1, sin_spread = 0;
  float cos_falloff = 0;
  float intensity = 0;
  bool two_sided = false;
};

ImportanceBounds importance_bounds(const LightBounds& bounds);

namespace importance_detail {
inline float safe_sqrt(float x) { return std::sqrt(std::max(0.0f, x)); }
// cos(max(0, a - b)) and sin(max(0, a - b)) from the sines and cosines of angles a, b in [0, pi].
inline float cos_of_difference_clamped(float sin_a, float cos_a, float sin_b, float cos_b) {
  if (cos_a > cos_b) return 1;
  return cos_a * cos_b + sin_a * sin_b;
}
inline float sin_of_difference_clamped(float sin_a, float cos_a, float sin_b, float cos_b) {
  if (cos_a > cos_b) return 0;
  return sin_a * cos_b - cos_a * sin_b;
}
}  // namespace importance_detail

// Estimated light from the group at point `p` of a surface with unit normal `n` (zero vector for a
// point in a medium): intensity x the largest emitter cosine any light of the group can have
// towards p x the largest receiver cosine / squared distance; 0 only when no light of the group
// can reach p. Conservative: never 0 for a group that lights p. The light BVH rates eight groups
// at once with importance8() (importance8.h), which gives exactly this per lane; this is the
// formula's reference.
inline float importance(const ImportanceBounds& bounds, vec3 p, vec3 n) {
  using namespace importance_detail;
  if (!(bounds.intensity > 0)) return 0;
  vec3 to_point = p - bounds.center;
  float distance2 = length_squared(to_point);
  // Inside the bounding sphere every direction and cosine is possible: only the distance to the
  // centre tells groups apart, clamped at half the radius so that a point near the centre of a
  // large group does not count it as all but touching. (Clamping at the whole radius made every
  // point inside alike, and a floor under a wide field of lamps chose between the field's halves
  // by brightness alone: 12% more error at equal samples on assets/many-lights.scene.)
  if (distance2 <= bounds.radius2) return bounds.intensity / std::max(std::max(distance2, bounds.radius2 * 0.25f), 1e-30f);

  // The long-latency steps of the light BVH's descent are square roots and divisions, one after
  // another: so one division for the whole evaluation, and every cosine and sine below first
  // found times the distance (dot products and square roots of squared lengths, which need no
  // division), then scaled by one over it. Only the division and one square root stay on the
  // descent's chain; the others run beside them.
  float axis_t = dot(bounds.axis, to_point);  // distance x cos theta_w
  if (bounds.two_sided) axis_t = std::abs(axis_t);
  float sin_w_t = safe_sqrt(distance2 - axis_t * axis_t);
  float cos_b_t = safe_sqrt(distance2 - bounds.radius2);
  float inv_distance2 = 1 / std::max(distance2, 1e-30f);
  float inv_distance = std::sqrt(inv_distance2);
  // theta_w: between the cone's axis and the direction from the group to p.
  float cos_w = axis_t * inv_distance, sin_w = sin_w_t * inv_distance;
  // theta_b: the half-angle the bounding sphere subtends at p.
  float sin_b = std::min(bounds.radius * inv_distance, 1.0f), cos_b = cos_b_t * inv_distance;
  // theta': the smallest angle between an emitting normal and the direction to p.
  float cos_x = cos_of_difference_clamped(sin_w, cos_w, bounds.sin_spread, bounds.cos_spread);
  float sin_x = sin_of_difference_clamped(sin_w, cos_w, bounds.sin_spread, bounds.cos_spread);
  float cos_emitter = cos_of_difference_clamped(sin_x, cos_x, sin_b, cos_b);
  if (cos_emitter <= bounds.cos_falloff) return 0;

  float estimate = bounds.intensity * inv_distance2 * cos_emitter;  // the first product off the chain
  if (!(n.x == 0 && n.y == 0 && n.z == 0)) {
    // Either side of the surface: a BSDF may transmit.
    float normal_t = std::abs(dot(to_point, n));  // distance x cos theta_i
    float cos_i = normal_t * inv_distance, sin_i = safe_sqrt(distance2 - normal_t * normal_t) * inv_distance;
    estimate *= cos_of_difference_clamped(sin_i, cos_i, sin_b, cos_b);
  }
  return std::max(estimate, 0.0f);
}

// The directional measure of pbrt-v4's split cost: the solid angle the group's cone of normals
// widened by its falloff covers, weighted by cosine.
float orientation_measure(const LightBounds& bounds);

}  // namespace radiant
