// Eight groups' importance at once (light_bounds.h): the light BVH's descent rates every child of
// a node in one pass. The rating is a plain loop over the eight lanes without branches, which GCC
// vectorises: one eight-wide pass where the caller is compiled for AVX2, two four-wide passes on
// the x86-64 baseline. Either way each lane is importance() of its group to the bit (the same
// operations in the same order, no fused multiply-adds), so the choice does not depend on the
// instruction set. Inline, because the descent is one chain of dependent steps and a call would
// lengthen every link.
#pragma once

#include "lights/light_bounds.h"
#include "math/lane_isa.h"

namespace radiant {

constexpr int light_node_width = 8;

// Eight groups' ImportanceBounds side by side, one lane each; a lane of intensity 0 is empty.
struct ImportanceBounds8 {
  alignas(32) float center_x[light_node_width] = {};
  alignas(32) float center_y[light_node_width] = {};
  alignas(32) float center_z[light_node_width] = {};
  alignas(32) float radius[light_node_width] = {};
  alignas(32) float radius2[light_node_width] = {};
  alignas(32) float axis_x[light_node_width] = {};
  alignas(32) float axis_y[light_node_width] = {};
  alignas(32) float axis_z[light_node_width] = {};
  alignas(32) float cos_spread[light_node_width] = {};
  alignas(32) float sin_spread[light_node_width] = {};
  alignas(32) float cos_falloff[light_node_width] = {};
  alignas(32) float intensity[light_node_width] = {};
  alignas(32) float two_sided[light_node_width] = {};  // 1 or 0
};

void set_lane(ImportanceBounds8& bounds, int lane, const ImportanceBounds& one);
ImportanceBounds lane_of(const ImportanceBounds8& bounds, int lane);

namespace importance8_detail {

// importance() of each lane's group at (p, n), for a point on a surface (HasNormal) or in a
// medium. importance()'s branches on a lane become selects: both sides are worked out and one is
// kept, which gives the same value as the branch taken. (A select on the point's own kind inside
// the loop would stop GCC from vectorising it, hence the two instances.)
template <bool HasNormal>
[[gnu::always_inline]] inline void rate_lanes(const ImportanceBounds8& b, vec3 p, vec3 n, float* out) {
  using namespace importance_detail;
  for (int i = 0; i < light_node_width; ++i) {
    float tx = p.x - b.center_x[i], ty = p.y - b.center_y[i], tz = p.z - b.center_z[i];
    float distance2 = (tx * tx + ty * ty) + tz * tz;
    float radius2 = b.radius2[i], intensity = b.intensity[i];
    // Inside the bounding sphere.
    float clamped = std::max(std::max(distance2, radius2 * 0.25f), 1e-30f);
    float inside_value = intensity / clamped;
    // Outside it.
    float axis_t = (b.axis_x[i] * tx + b.axis_y[i] * ty) + b.axis_z[i] * tz;
    axis_t = b.two_sided[i] != 0 ? std::abs(axis_t) : axis_t;
    float sin_w_t = safe_sqrt(distance2 - axis_t * axis_t);
    float cos_b_t = safe_sqrt(distance2 - radius2);
    float inv_distance2 = 1 / std::max(distance2, 1e-30f);
    float inv_distance = std::sqrt(inv_distance2);
    float cos_w = axis_t * inv_distance, sin_w = sin_w_t * inv_distance;
    float sin_b = std::min(b.radius[i] * inv_distance, 1.0f), cos_b = cos_b_t * inv_distance;
    float cos_x = cos_of_difference_clamped(sin_w, cos_w, b.sin_spread[i], b.cos_spread[i]);
    float sin_x = sin_of_difference_clamped(sin_w, cos_w, b.sin_spread[i], b.cos_spread[i]);
    float cos_emitter = cos_of_difference_clamped(sin_x, cos_x, sin_b, cos_b);
    float estimate = intensity * inv_distance2 * cos_emitter;
    if constexpr (HasNormal) {
      float normal_t = std::abs((tx * n.x + ty * n.y) + tz * n.z);
      float cos_i = normal_t * inv_distance, sin_i = safe_sqrt(distance2 - normal_t * normal_t) * inv_distance;
      estimate *= cos_of_difference_clamped(sin_i, cos_i, sin_b, cos_b);
    }
    float outside_value = cos_emitter <= b.cos_falloff[i] ? 0.0f : std::max(estimate, 0.0f);
    float value = distance2 <= radius2 ? inside_value : outside_value;
    out[i] = intensity > 0 ? value : 0.0f;
  }
}

}  // namespace importance8_detail

// importance() of each lane's group at (p, n), into out[0..7].
[[gnu::always_inline]] inline void importance8(const ImportanceBounds8& b, vec3 p, vec3 n, float* out) {
  if (n.x == 0 && n.y == 0 && n.z == 0)
    importance8_detail::rate_lanes<false>(b, p, n, out);
  else
    importance8_detail::rate_lanes<true>(b, p, n, out);
}

// importance8 out of line, compiled for `isa` as the light BVH's descent compiles it (for the tests:
// every instruction set must rate each lane as importance() does).
void importance8_on(const ImportanceBounds8& bounds, vec3 p, vec3 n, float* out, LaneIsa isa);

}  // namespace radiant
