// The strata of the grid and jittered samplers, shared by sample_pixel and its lanes
// (draw_stratified_pixels): nx * ny cells with nx * ny >= samples, visited in a per-pixel
// pseudo-random order.
#pragma once

#include <cstdint>

#include "math/fast_divisor.h"

namespace radiant {

struct Strata {
  uint32_t samples = 0;
  FastDivisor nx, ny, cells;
};

// The strata for `samples`, as square as possible, worked out once per thread while the count
// stays the same (the square root and the divisors cost more than the rest of a pixel sample).
// (The divisions by the strata counts are FastDivisor's: the jittered sampler divided five times
// per sample, an eighth of a Whitted render's time at 81 samples.)
const Strata& strata(uint32_t samples);

// Kensler's (2013) permutation of [0, length): `mask` is length - 1 with every bit below its
// highest set. One round maps i inside [0, mask]; rounds repeat while the result is >= length.
[[gnu::always_inline]] inline uint32_t permutation_round(uint32_t i, uint32_t seed, uint32_t mask) {
  i ^= seed, i *= 0xe170893dU, i ^= seed >> 16, i ^= (i & mask) >> 4, i ^= seed >> 8, i *= 0x0929eb3fU;
  i ^= seed >> 23, i ^= (i & mask) >> 1, i *= 1 | seed >> 27, i *= 0x6935fa69U, i ^= (i & mask) >> 11;
  i *= 0x74dcb303U, i ^= (i & mask) >> 2, i *= 0x9e501cc3U, i ^= (i & mask) >> 2, i *= 0xc860a3dfU;
  i &= mask, i ^= i >> 5;
  return i;
}
inline uint32_t permutation_mask(uint32_t length) {
  uint32_t w = length - 1;
  w |= w >> 1, w |= w >> 2, w |= w >> 4, w |= w >> 8, w |= w >> 16;
  return w;
}

// Element i of the permutation of [0, length) chosen by `seed`.
inline uint32_t permutation_element(uint32_t i, const FastDivisor& length, uint32_t seed) {
  if (length.d <= 1) return 0;
  uint32_t mask = permutation_mask(length.d);
  do i = permutation_round(i, seed, mask);
  while (i >= length.d);
  return length.remainder(i + seed);
}

// The seed of a pixel's order of strata.
constexpr uint32_t strata_order_seed_salt = 0x5354u;

}  // namespace radiant
