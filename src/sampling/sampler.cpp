#include "sampling/sampler.h"

#include <algorithm>
#include <cmath>

#include "math/fast_divisor.h"
#include "sampling/hash.h"

namespace radiant {

namespace {

constexpr uint32_t reverse_bits(uint32_t v) {
  v = __builtin_bswap32(v);  // one instruction for the byte and half-word stages (GCC, Clang)
  v = ((v >> 1) & 0x55555555U) | ((v & 0x55555555U) << 1);
  v = ((v >> 2) & 0x33333333U) | ((v & 0x33333333U) << 2);
  return ((v >> 4) & 0x0F0F0F0FU) | ((v & 0x0F0F0F0FU) << 4);
}

// Sobol dimension 1 (primitive polynomial x + 1: m_k = m_{k-1} ^ 2 m_{k-1}), bit-reversed and
// tabulated per byte of the index: four lookups instead of a loop over its 32 bits.
struct Sobol1Tables {
  uint32_t byte[4][256];
};
constexpr Sobol1Tables make_sobol1_tables() {
  uint32_t columns[32] = {};
  uint32_t m = 1;
  for (int k = 0; k < 32; ++k) {
    columns[k] = reverse_bits(m << (31 - k));
    m = m ^ (m << 1);
  }
  Sobol1Tables t{};
  for (int b = 0; b < 4; ++b)
    for (uint32_t value = 0; value < 256; ++value)
      for (int bit = 0; bit < 8; ++bit)
        if (value & (1u << bit)) t.byte[b][value] ^= columns[8 * b + bit];
  return t;
}
constexpr Sobol1Tables sobol1_tables = make_sobol1_tables();

// Sobol dimension 1 of `index`, bit-reversed.
uint32_t sobol1_reversed(uint32_t index) {
  return sobol1_tables.byte[0][index & 0xFF] ^ sobol1_tables.byte[1][(index >> 8) & 0xFF] ^
         sobol1_tables.byte[2][(index >> 16) & 0xFF] ^ sobol1_tables.byte[3][index >> 24];
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

// Element i of a pseudo-random permutation of [0, length) chosen by `seed` (Kensler 2013).
uint32_t permutation_element(uint32_t i, const FastDivisor& length, uint32_t seed) {
  if (length.d <= 1) return 0;
  uint32_t w = length.d - 1;
  w |= w >> 1, w |= w >> 2, w |= w >> 4, w |= w >> 8, w |= w >> 16;
  do {
    i ^= seed, i *= 0xe170893dU, i ^= seed >> 16, i ^= (i & w) >> 4, i ^= seed >> 8, i *= 0x0929eb3fU;
    i ^= seed >> 23, i ^= (i & w) >> 1, i *= 1 | seed >> 27, i *= 0x6935fa69U, i ^= (i & w) >> 11;
    i *= 0x74dcb303U, i ^= (i & w) >> 2, i *= 0x9e501cc3U, i ^= (i & w) >> 2, i *= 0xc860a3dfU;
    i &= w, i ^= i >> 5;
  } while (i >= length.d);
  return length.remainder(i + seed);
}

// Shuffled, Owen-scrambled Sobol (Burley 2020, "Practical Hash-based Owen Scrambling"): each pair
// of dimensions is the first two Sobol dimensions, Owen-scrambled by its own seeds, with the
// sample index itself Owen-scrambled (shuffled) by a third, so that pairs are not correlated
// with each other. The shuffle maps every aligned block of 2^k indices onto an aligned block,
// so the first 2^k samples of a pixel are still a (0,k,2)-net in every pair. The pixel pair
// keeps the unshuffled order (every prefix of a pixel's samples is then well spread, for
// progressive and adaptive rendering).
struct ShuffledSobol {
  uint32_t index;  // the shuffled sample index
  uint32_t seed;   // of this pair; the two scrambles derive from it
};
ShuffledSobol shuffled_sobol(const SampleContext& c, uint32_t dimension) {
  uint32_t h = hash3(c.pixel, dimension, c.seed);
  uint32_t index = dimension == 0 ? c.index : reverse_bits(laine_karras(reverse_bits(c.index), h));
  return {index, h};
}
// Sobol dimension 0 is the radical inverse: its bit-reversed digits are the index itself.
float sobol_x(const ShuffledSobol& s) {
  return bits_to_unit_float(reverse_bits(laine_karras(s.index, mix_bits(s.seed ^ 0xa511e9b3U))));
}
float sobol_y(const ShuffledSobol& s) {
  return bits_to_unit_float(reverse_bits(laine_karras(sobol1_reversed(s.index), mix_bits(s.seed ^ 0x63d83595U))));
}

float random_value(const SampleContext& c, uint32_t dimension) {
  return bits_to_unit_float(hash4(c.pixel, c.index, dimension, c.seed));
}

// Strata for grid/jittered: nx * ny cells with nx * ny >= samples, as square as possible.
struct Strata {
  uint32_t samples = 0;
  FastDivisor nx, ny, cells;
};
// The strata for `samples`, worked out once per thread while the count stays the same (the
// square root and the divisors cost more than the rest of a pixel sample).
// (The divisions by the strata counts are FastDivisor's: the jittered sampler divided five times
// per sample, an eighth of a Whitted render's time at 81 samples.)
const Strata& strata(uint32_t samples) {
  thread_local Strata s;
  if (s.samples != samples) {
    uint32_t nx = uint32_t(std::ceil(std::sqrt(double(samples))));
    uint32_t ny = (samples + nx - 1) / nx;
    s = {samples, FastDivisor(nx), FastDivisor(ny), FastDivisor(nx * ny)};
  }
  return s;
}

}  // namespace

vec2 sample_pixel(const SampleContext& c) {
  switch (c.kind) {
    case SamplerKind::grid:
    case SamplerKind::jittered: {
      if (c.samples <= 1) return {0.5f, 0.5f};
      const Strata& grid = strata(c.samples);
      // Strata in a per-pixel random order, so that the first k samples of a render stopped
      // early (time limit, noise threshold) are spread over the pixel, not its top rows. The
      // jitter belongs to the stratum, so the full set of positions does not depend on the order.
      uint32_t cell = permutation_element(grid.cells.remainder(c.index), grid.cells, hash3(c.pixel, c.seed, 0x5354u));
      vec2 offset = {0.5f, 0.5f};
      if (c.kind == SamplerKind::jittered)
        offset = {bits_to_unit_float(hash4(c.pixel, cell, 0, c.seed)), bits_to_unit_float(hash4(c.pixel, cell, 1, c.seed))};
      return {(float(grid.nx.remainder(cell)) + offset.x) / float(grid.nx.d),
              (float(grid.nx.quotient(cell)) + offset.y) / float(grid.ny.d)};
    }
    case SamplerKind::random:
      return {random_value(c, 0), random_value(c, 1)};
    case SamplerKind::sobol:
      return sample_2d(c, 0);
  }
  return {0.5f, 0.5f};
}

float sample_1d(const SampleContext& c, uint32_t dimension) {
  if (c.kind != SamplerKind::sobol) return random_value(c, dimension);
  return sobol_x(shuffled_sobol(c, dimension));
}

vec2 sample_2d(const SampleContext& c, uint32_t dimension) {
  if (c.kind != SamplerKind::sobol) return {random_value(c, dimension), random_value(c, dimension + 1)};
  ShuffledSobol s = shuffled_sobol(c, dimension);
  return {sobol_x(s), sobol_y(s)};
}

}  // namespace radiant
