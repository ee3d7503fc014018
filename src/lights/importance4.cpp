// Four groups' importance at once (light_bounds.h): the light BVH's descent rates every child of a
// node in one pass, with SSE2 (every x86-64 CPU has it) and a lane-by-lane loop elsewhere.
#include <algorithm>

#include "lights/light_bounds.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace radiant {

void set_lane(ImportanceBounds4& bounds, int lane, const ImportanceBounds& one) {
  bounds.center_x[lane] = one.center.x, bounds.center_y[lane] = one.center.y, bounds.center_z[lane] = one.center.z;
  bounds.radius[lane] = one.radius, bounds.radius2[lane] = one.radius2;
  bounds.axis_x[lane] = one.axis.x, bounds.axis_y[lane] = one.axis.y, bounds.axis_z[lane] = one.axis.z;
  bounds.cos_spread[lane] = one.cos_spread, bounds.sin_spread[lane] = one.sin_spread;
  bounds.cos_falloff[lane] = one.cos_falloff;
  bounds.intensity[lane] = one.intensity;
  bounds.two_sided[lane] = one.two_sided ? 1.0f : 0.0f;
}

ImportanceBounds lane_of(const ImportanceBounds4& bounds, int lane) {
  ImportanceBounds one;
  one.center = {bounds.center_x[lane], bounds.center_y[lane], bounds.center_z[lane]};
  one.radius = bounds.radius[lane], one.radius2 = bounds.radius2[lane];
  one.axis = {bounds.axis_x[lane], bounds.axis_y[lane], bounds.axis_z[lane]};
  one.cos_spread = bounds.cos_spread[lane], one.sin_spread = bounds.sin_spread[lane];
  one.cos_falloff = bounds.cos_falloff[lane];
  one.intensity = bounds.intensity[lane];
  one.two_sided = bounds.two_sided[lane] != 0;
  return one;
}

#if defined(__SSE2__)

namespace {

using f4 = __m128;
f4 load(const float* v) { return _mm_loadu_ps(v); }
f4 splat(float v) { return _mm_set1_ps(v); }
f4 select(f4 mask, f4 if_true, f4 if_false) { return _mm_or_ps(_mm_and_ps(mask, if_true), _mm_andnot_ps(mask, if_false)); }
f4 abs4(f4 v) { return _mm_andnot_ps(splat(-0.0f), v); }
// The scalar safe_sqrt: max first, with the zero as the first operand as std::max(0.0f, x) has it
// (maxps returns its second operand when either is NaN, as std::max returns its first).
f4 safe_sqrt4(f4 x) { return _mm_sqrt_ps(_mm_max_ps(x, splat(0.0f))); }
f4 cos_of_difference_clamped4(f4 sin_a, f4 cos_a, f4 sin_b, f4 cos_b) {
  f4 value = _mm_add_ps(_mm_mul_ps(cos_a, cos_b), _mm_mul_ps(sin_a, sin_b));
  return select(_mm_cmpgt_ps(cos_a, cos_b), splat(1.0f), value);
}
f4 sin_of_difference_clamped4(f4 sin_a, f4 cos_a, f4 sin_b, f4 cos_b) {
  f4 value = _mm_sub_ps(_mm_mul_ps(sin_a, cos_b), _mm_mul_ps(cos_a, sin_b));
  return select(_mm_cmpgt_ps(cos_a, cos_b), splat(0.0f), value);
}

}  // namespace

void importance4(const ImportanceBounds4& b, vec3 p, vec3 n, float out[4]) {
  f4 intensity = load(b.intensity), radius2 = load(b.radius2);
  f4 tx = _mm_sub_ps(splat(p.x), load(b.center_x)), ty = _mm_sub_ps(splat(p.y), load(b.center_y)),
     tz = _mm_sub_ps(splat(p.z), load(b.center_z));
  f4 distance2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(tx, tx), _mm_mul_ps(ty, ty)), _mm_mul_ps(tz, tz));
  // Inside the bounding sphere (importance()'s first branch).
  f4 tiny = splat(1e-30f);
  f4 clamped = _mm_max_ps(_mm_max_ps(_mm_mul_ps(radius2, splat(0.25f)), distance2), tiny);
  f4 inside_value = _mm_div_ps(intensity, clamped);
  // Outside it.
  f4 inv_distance2 = _mm_div_ps(splat(1.0f), _mm_max_ps(distance2, tiny));
  f4 inv_distance = _mm_sqrt_ps(inv_distance2);
  f4 wx = _mm_mul_ps(tx, inv_distance), wy = _mm_mul_ps(ty, inv_distance), wz = _mm_mul_ps(tz, inv_distance);
  f4 cos_w = _mm_add_ps(_mm_add_ps(_mm_mul_ps(load(b.axis_x), wx), _mm_mul_ps(load(b.axis_y), wy)),
                        _mm_mul_ps(load(b.axis_z), wz));
  cos_w = select(_mm_cmpneq_ps(load(b.two_sided), splat(0.0f)), abs4(cos_w), cos_w);
  f4 sin_w = safe_sqrt4(_mm_sub_ps(splat(1.0f), _mm_mul_ps(cos_w, cos_w)));
  f4 sin_b = _mm_min_ps(_mm_mul_ps(load(b.radius), inv_distance), splat(1.0f));
  f4 cos_b = safe_sqrt4(_mm_sub_ps(splat(1.0f), _mm_mul_ps(sin_b, sin_b)));
  f4 cos_o = load(b.cos_spread), sin_o = load(b.sin_spread);
  f4 cos_x = cos_of_difference_clamped4(sin_w, cos_w, sin_o, cos_o);
  f4 sin_x = sin_of_difference_clamped4(sin_w, cos_w, sin_o, cos_o);
  f4 cos_emitter = cos_of_difference_clamped4(sin_x, cos_x, sin_b, cos_b);
  f4 estimate = _mm_mul_ps(_mm_mul_ps(intensity, cos_emitter), inv_distance2);
  if (!(n.x == 0 && n.y == 0 && n.z == 0)) {
    f4 cos_i = abs4(_mm_add_ps(_mm_add_ps(_mm_mul_ps(wx, splat(n.x)), _mm_mul_ps(wy, splat(n.y))),
                               _mm_mul_ps(wz, splat(n.z))));
    f4 sin_i = safe_sqrt4(_mm_sub_ps(splat(1.0f), _mm_mul_ps(cos_i, cos_i)));
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

void importance4(const ImportanceBounds4& bounds, vec3 p, vec3 n, float out[4]) {
  for (int lane = 0; lane < 4; ++lane) out[lane] = importance(lane_of(bounds, lane), p, n);
}

#endif

}  // namespace radiant
