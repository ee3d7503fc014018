// A ray and the robust spawning of secondary rays from a surface.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "math/vec.h"

namespace radiant {

struct Ray {
  vec3 origin;
  vec3 direction;  // not necessarily unit
  float tmax = std::numeric_limits<float>::infinity();
  // When within the shutter the ray travels, in [0, 1] (scene/motion_steps.h); 0 without motion.
  float time = 0;
};

// Whether a ray along `direction` meets a surface on its front, the side its geometric normal
// `normal` (times `orientation`, -1 where a mirroring transform turned it) points to.
inline bool arrives_on_front(vec3 direction, vec3 normal, float orientation = 1) {
  return orientation * dot(direction, normal) < 0;
}

// Bound on the relative rounding error of n floating-point operations (pbrt's gamma(n)).
constexpr float rounding_gamma(int n) {
  constexpr float epsilon = std::numeric_limits<float>::epsilon() * 0.5f;
  return (n * epsilon) / (1 - n * epsilon);
}

// The next float towards +infinity (or -infinity when `up` is false), as std::nextafter does
// but inline: it runs three times for every ray spawned. Infinities and NaN stay as they are.
// Written with selects rather than early returns: fewer instructions than the branches were.
// (GCC still branches on whether an axis steps at all, in offset_ray_origin; forcing that into
// a mask cost more than the mispredictions it saved, docs/performance.md "Cheaper hits".)
inline float next_float(float v, bool up) {
  uint32_t bits = std::bit_cast<uint32_t>(v);
  uint32_t stepped = bits + (((v > 0) == up) ? 1u : ~0u);  // away from zero one ulp up, towards it one down
  uint32_t from_zero = up ? 1u : 0x80000001u;              // either zero: the smallest denormal that way
  stepped = v == 0 ? from_zero : stepped;
  bool finite = (bits & 0x7f800000u) != 0x7f800000u;
  return std::bit_cast<float>(finite ? stepped : bits);
}

// Moves `p` off the surface with normal `n` along the side `w` points to, by the projection of
// the per-axis error bound `error` onto the normal, then one more ulp away from the surface:
// the spawned ray cannot re-hit the surface it leaves, wherever that surface is. Always inlined:
// called, it takes four vec3 by value, and their packing stalls on store forwarding.
[[gnu::always_inline]] inline vec3 offset_ray_origin(vec3 p, vec3 error, vec3 n, vec3 w) {
  vec3 away = dot(w, n) < 0 ? -n : n;
  // An exact hit (a zero coordinate of an axis-aligned surface) has a zero error bound; the
  // floor keeps its step out of the denormals, which Embree's kernels flush to zero (t = -0 hits).
  constexpr float min_offset = 1e-20f;
  vec3 po = p + away * std::max(dot(abs(n), error), min_offset);
  // The ulp step follows the normal, not the offset, so that it is never skipped.
  auto step = [](float coordinate, float normal) { return normal != 0 ? next_float(coordinate, normal > 0) : coordinate; };
  return {step(po.x, away.x), step(po.y, away.y), step(po.z, away.z)};
}

}  // namespace radiant
