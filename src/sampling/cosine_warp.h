// The cosine-weighted hemisphere warp as inline arithmetic: sample_cosine_hemisphere warps one
// sample, cosine_hemisphere_many a batch's in SIMD, and both must give the same bits, so both
// are this function.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "math/lane_isa.h"
#include "math/vec.h"

namespace radiant {

// sin and cos of |theta| <= pi/4 by their Taylor series, truncated where the next term falls
// below float precision (theta^11/11! < 2e-9, theta^10/10! < 3e-8). The libm call and its range
// reduction cost more than the rest of a cosine-weighted sample.
inline void sin_cos_quarter(float theta, float& s, float& c) {
  float t2 = theta * theta;
  s = theta * (1 + t2 * (-1.0f / 6 + t2 * (1.0f / 120 + t2 * (-1.0f / 5040 + t2 * (1.0f / 362880)))));
  c = 1 + t2 * (-0.5f + t2 * (1.0f / 24 + t2 * (-1.0f / 720 + t2 * (1.0f / 40320))));
}

// Cosine-weighted direction around +z for (ux, uy) in [0,1)^2; pdf = cos(theta) / pi.
inline vec3 cosine_hemisphere(float ux, float uy) {
  // Concentric disk mapping (Shirley-Chiu), lifted to the hemisphere. The angle within the
  // major axis's wedge is theta = (pi/4) * minor/major; on the b-major wedges phi = pi/2 - theta,
  // which swaps sine and cosine. One division, no trigonometric call, and no branch on the
  // wedge: which axis is major is a coin flip no branch predictor can learn.
  float a = 2 * ux - 1, b = 2 * uy - 1;
  // A bit mask, not a float 0/1 or a ternary: GCC turns both of those back into a branch.
  uint32_t a_major = 0u - uint32_t(std::abs(a) > std::abs(b));
  auto pick = [a_major](float if_a_major, float otherwise) {
    return std::bit_cast<float>((std::bit_cast<uint32_t>(if_a_major) & a_major) |
                                (std::bit_cast<uint32_t>(otherwise) & ~a_major));
  };
  float r = pick(a, b);
  float s, c;
  sin_cos_quarter((pi / 4) * (pick(b, a) / r), s, c);
  float x = r * pick(c, s), y = r * pick(s, c), z = std::sqrt(std::max(0.0f, 1 - r * r));
  // The centre, where the division above gives NaN, is the pole: chosen after the arithmetic,
  // not by returning before it, so that a loop over many samples vectorises.
  uint32_t off_centre = 0u - uint32_t((a != 0) | (b != 0));
  auto unless_centre = [off_centre](float value, float at_centre) {
    return std::bit_cast<float>((std::bit_cast<uint32_t>(value) & off_centre) |
                                (std::bit_cast<uint32_t>(at_centre) & ~off_centre));
  };
  return {unless_centre(x, 0), unless_centre(y, 0), unless_centre(z, 1)};
}

// cosine_hemisphere for `count` samples (u_x[i], u_y[i]), into x, y, z: the same bits, in SIMD.
void cosine_hemisphere_many(const float* u_x, const float* u_y, int count, float* x, float* y, float* z,
                            LaneIsa isa = LaneIsa::best);

}  // namespace radiant
