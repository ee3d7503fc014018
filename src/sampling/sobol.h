// The shuffled, Owen-scrambled Sobol pairs behind SamplerKind::sobol, as inline integer
// arithmetic: sample_2d draws one pair, sample_2d_many many at once in SIMD, and both must give
// the same bits, so both are built from these functions.
#pragma once

#include <cstdint>

#include "sampling/hash.h"

namespace radiant::sobol {

constexpr uint32_t reverse_bits(uint32_t v) {
  v = __builtin_bswap32(v);  // one instruction for the byte and half-word stages (GCC, Clang)
  v = ((v >> 1) & 0x55555555U) | ((v & 0x55555555U) << 1);
  v = ((v >> 2) & 0x33333333U) | ((v & 0x33333333U) << 2);
  return ((v >> 4) & 0x0F0F0F0FU) | ((v & 0x0F0F0F0FU) << 4);
}

// Sobol dimension 1 of `index`, bit-reversed. Its generator matrix is Pascal's triangle mod 2
// (primitive polynomial x + 1: m_k = m_{k-1} ^ 2 m_{k-1}), so by Lucas' theorem index bit k
// reaches reversed output bit p exactly when the bits of p are a subset of those of k: output
// bit p is the XOR of the index bits at every superset of p, five shift-and-mask steps, one per
// bit of a position. (No table: the SIMD version would need a gather.)
constexpr uint32_t sobol1_reversed(uint32_t x) {
  x ^= (x >> 1) & 0x55555555U;
  x ^= (x >> 2) & 0x33333333U;
  x ^= (x >> 4) & 0x0F0F0F0FU;
  x ^= (x >> 8) & 0x00FF00FFU;
  x ^= (x >> 16) & 0x0000FFFFU;
  return x;
}

// The Laine-Karras hash: each bit is flipped by a function of the bits below it and the seed
// (the constants of Burley 2020 / pbrt-v4's FastOwenScrambler). Applied to bit-reversed digits
// it is a nested uniform (Owen) scramble.
constexpr uint32_t laine_karras(uint32_t v, uint32_t seed) {
  v ^= v * 0x3d20adeaU;
  v += seed;
  v *= (seed >> 16) | 1;
  v ^= v * 0x05526c56U;
  v ^= v * 0x53a22864U;
  return v;
}

// Shuffled, Owen-scrambled Sobol (Burley 2020, "Practical Hash-based Owen Scrambling"): each pair
// of dimensions is the first two Sobol dimensions, Owen-scrambled by its own seeds, with the
// sample index itself Owen-scrambled (shuffled) by a third, so that pairs are not correlated
// with each other. The shuffle maps every aligned block of 2^k indices onto an aligned block,
// so the first 2^k samples of a pixel are still a (0,k,2)-net in every pair. The pixel pair
// keeps the unshuffled order (every prefix of a pixel's samples is then well spread, for
// progressive and adaptive rendering).
struct ShuffledIndex {
  uint32_t index;  // the shuffled sample index
  uint32_t seed;   // of this pair; the two scrambles derive from it
};
constexpr ShuffledIndex shuffle(uint32_t pixel, uint32_t index, uint32_t dimension, uint32_t seed) {
  uint32_t h = hash3(pixel, dimension, seed);
  uint32_t shuffled = dimension == 0 ? index : reverse_bits(laine_karras(reverse_bits(index), h));
  return {shuffled, h};
}
// Sobol dimension 0 is the radical inverse: its bit-reversed digits are the index itself.
constexpr uint32_t x_bits(ShuffledIndex s) {
  return reverse_bits(laine_karras(s.index, mix_bits(s.seed ^ 0xa511e9b3U)));
}
constexpr uint32_t y_bits(ShuffledIndex s) {
  return reverse_bits(laine_karras(sobol1_reversed(s.index), mix_bits(s.seed ^ 0x63d83595U)));
}

}  // namespace radiant::sobol
