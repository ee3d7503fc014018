// The lane: what shading code is written over, once, for a single path and for the batch. The
// batch keeps its vertices as arrays of structure fields (integrators/surface_lanes.h) and runs
// the same per-lane code in loops that GCC vectorises (lane_isa.h), as ISPC runs a program
// instance's code: one call is one lane, a `bool` its mask. So shading written over a lane has
// no data-dependent branch (a vector loop cannot take one): a branch is a mask and a select,
// with both sides worked out and the unwanted one dropped. The helpers below are those masks
// and selects; Fresnel, GGX, ray offsets and hit decoding are written with them.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "math/vec.h"

namespace radiant::lane {

constexpr float largest_float = std::numeric_limits<float>::max();

// std::isfinite as comparisons, which a vector loop can take.
[[gnu::always_inline]] inline bool finite(float x) { return std::abs(x) <= largest_float; }
[[gnu::always_inline]] inline bool finite(vec3 a) { return finite(a.x) & finite(a.y) & finite(a.z); }
[[gnu::always_inline]] inline bool black(vec3 a) { return (a.x == 0) & (a.y == 0) & (a.z == 0); }
// A per-component select: a ternary on whole vectors is a branch GCC does not if-convert.
[[gnu::always_inline]] inline vec3 select(bool c, vec3 a, vec3 b) {
  return {c ? a.x : b.x, c ? a.y : b.y, c ? a.z : b.z};
}

// `x` where `keep`, else +0: the select written on the bits. As a float select, GCC folds the
// comparisons callers make of the result into selects of booleans, which it cannot vectorise.
[[gnu::always_inline]] inline float zero_unless(bool keep, float x) {
  return std::bit_cast<float>(std::bit_cast<uint32_t>(x) & (keep ? ~0u : 0u));
}

// select() written on the bits, for a choice GCC must not turn back into a branch: sunk into
// one, the chosen side's loads become conditional, which the SSE2 loops cannot vectorise.
[[gnu::always_inline]] inline float select_bits(bool c, float a, float b) {
  uint32_t mask = c ? ~0u : 0u;
  return std::bit_cast<float>((std::bit_cast<uint32_t>(a) & mask) | (std::bit_cast<uint32_t>(b) & ~mask));
}
[[gnu::always_inline]] inline vec3 select_bits(bool c, vec3 a, vec3 b) {
  return {select_bits(c, a.x, b.x), select_bits(c, a.y, b.y), select_bits(c, a.z, b.z)};
}

// normalize() without its rescaling branch: `in_range` says whether the result is normalize()'s.
[[gnu::always_inline]] inline vec3 normalize_in_range(vec3 a, bool& in_range) {
  float l2 = dot(a, a);
  in_range = (l2 >= std::numeric_limits<float>::min()) & (l2 <= std::numeric_limits<float>::max());
  return a * (1 / std::sqrt(l2));
}

}  // namespace radiant::lane
