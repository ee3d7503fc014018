// Four groups' importance at once (light_bounds.h): the light BVH's descent rates every child of a
// node in one pass, with SSE2 (every x86-64 CPU has it) and a lane-by-lane loop elsewhere. Inline,
// because the descent is one chain of dependent steps and a call would lengthen every link.
#pragma once

#include "lights/light_bounds.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace radiant {

// Four groups' ImportanceBounds side by side, one lane each; a lane of intensity 0 is empty.
struct ImportanceBounds4 {
  float center_x[4] = {}, center_y[4] = {}, center_z[4] = {};
  float radius[4] = {}, radius2[4] = {};
  float axis_x[4] = {}, axis_y[4] = {}, axis_z[4] = {};
  float cos_spread[4] = {}, sin_spread[4] = {}, cos_falloff[4] = {};
  float intensity[4] = {};
  float two_sided[4] = {};  // 1 or 0
};

void set_lane(ImportanceBounds4& bounds, int lane, const ImportanceBounds& one);
ImportanceBounds lane_of(const ImportanceBounds4& bounds, int lane);

#if defined(__SSE2__)

namespace importance4_detail {

using f4 = __m128;
inline f4 load(const float* v) { return _mm_loadu_ps(v); }
inline f4 splat(float v) { return _mm_set1_ps(v); }
inline f4 select(f4 mask, f4 if_true, f4 if_false) {
  return _mm_or_ps(_mm_and_ps(mask, if_true), _mm_andnot_ps(mask, if_false));
}
inline f4 abs4(f4 v) { return _mm_andnot_ps(splat(-0.0f), v); }
// The scalar safe_sqrt: max first, with the zero as the first operand as std::max(0.0f, x) has it
// (maxps returns its second operand when either is NaN, as std::max returns its first).
inline f4 safe_sqrt4(f4 x) { return _mm_sqrt_ps(_mm_max_ps(x, splat(0.0f))); }
// dot(a, b) in vec.h's order: (x + y) + z.
inline f4 dot4(f4 ax, f4 ay, f4 az, f4 bx, f4 by, f4 bz) {
  return _mm_add_ps(_mm_add_ps(_mm_mul_ps(ax, bx), _mm_mul_ps(ay, by)), _mm_mul_ps(az, bz));
}
inline f4 cos_of_difference_clamped4(f4 sin_a, f4 cos_a, f4 sin_b, f4 cos_b) {
  f4 value = _mm_add_ps(_mm_mul_ps(cos_a, cos_b), _mm_mul_ps(sin_a, sin_b));
  return select(_mm_cmpgt_ps(cos_a, cos_b), splat(1.0f), value);
}
inline f4 sin_of_difference_clamped4(f4 sin_a, f4 cos_a, f4 sin_b, f4 cos_b) {
  f4 value = _mm_sub_ps(_mm_mul_ps(sin_a, cos_b), _mm_mul_ps(cos_a, sin_b));
  return select(_mm_cmpgt_ps(cos_a, cos_b), splat(0.0f), value);
}

}  // namespace importance4_detail

// importance() of each lane's group at (p, n), all four at once: the same operations in the same
// order, so each lane gives exactly what importance() gives for that group.
inline void importance4(const ImportanceBounds4& b, vec3 p, vec3 n, float out[4]) {
  using namespace importance4_detail;
  f4 intensity = load(b.intensity), radius2 = load(b.radius2);
  f4 tx = _mm_sub_ps(splat(p.x), load(b.center_x)), ty = _mm_sub_ps(splat(p.y), load(b.center_y)),
     tz = _mm_sub_ps(splat(p.z), load(b.center_z));
  f4 distance2 = dot4(tx, ty, tz, tx, ty, tz);
  // Inside the bounding sphere (importance()'s first branch).
  f4 tiny = splat(1e-30f);
  f4 clamped = _mm_max_ps(_mm_max_ps(_mm_mul_ps(radius2, splat(0.25f)), distance2), tiny);
  f4 inside_value = _mm_div_ps(intensity, clamped);
  // Outside it.
  f4 axis_t = dot4(load(b.axis_x), load(b.axis_y), load(b.axis_z), tx, ty, tz);
  axis_t = select(_mm_cmpneq_ps(load(b.two_sided), splat(0.0f)), abs4(axis_t), axis_t);
  f4 sin_w_t = safe_sqrt4(_mm_sub_ps(distance2, _mm_mul_ps(axis_t, axis_t)));
  f4 cos_b_t = safe_sqrt4(_mm_sub_ps(distance2, radius2));
  f4 inv_distance2 = _mm_div_ps(splat(1.0f), _mm_max_ps(distance2, tiny));
  f4 inv_distance = _mm_sqrt_ps(inv_distance2);
  f4 cos_w = _mm_mul_ps(axis_t, inv_distance), sin_w = _mm_mul_ps(sin_w_t, inv_distance);
  f4 sin_b = _mm_min_ps(_mm_mul_ps(load(b.radius), inv_distance), splat(1.0f));
  f4 cos_b = _mm_mul_ps(cos_b_t, inv_distance);
  f4 cos_o = load(b.cos_spread), sin_o = load(b.sin_spread);
  f4 cos_x = cos_of_difference_clamped4(sin_w, cos_w, sin_o, cos_o);
  f4 sin_x = sin_of_difference_clamped4(sin_w, cos_w, sin_o, cos_o);
  f4 cos_emitter = cos_of_difference_clamped4(sin_x, cos_x, sin_b, cos_b);
  f4 estimate = _mm_mul_ps(_mm_mul_ps(intensity, inv_distance2), cos_emitter);
  if (!(n.x == 0 && n.y == 0 && n.z == 0)) {
    f4 normal_t = abs4(dot4(tx, ty, tz, splat(n.x), splat(n.y), splat(n.z)));
    f4 cos_i = _mm_mul_ps(normal_t, inv_distance);
    f4 sin_i = _mm_mul_ps(safe_sqrt4(_mm_sub_ps(distance2, _mm_mul_ps(normal_t, normal_t))), inv_distance);
    estimate = _mm_mul_ps(estimate, cos_of_difference_clamped4(sin_i, cos_i, sin_b, cos_b));
  }
  f4 outside_value = select(_mm_cmple_ps(cos_emitter, load(b.cos_falloff)), splat(0.0f),
                            _mm_max_ps(splat(0.0f), estimate));  // std::max(estimate, 0): NaN stays
  f4 value = select(_mm_cmple_ps(distance2, radius2), inside_value, outside_value);
  // `!(intensity > 0)` as importance() has it: an empty lane (or NaN intensity) rates 0.
  value = _mm_and_ps(_mm_cmpgt_ps(intensity, splat(0.0f)), value);
  _mm_storeu_ps(out, value);
}

#else

inline void importance4(const ImportanceBounds4& bounds, vec3 p, vec3 n, float out[4]) {
  for (int lane = 0; lane < 4; ++lane) out[lane] = importance(lane_of(bounds, lane), p, n);
}

#endif

}  // namespace radiant
