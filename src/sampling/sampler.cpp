#include "sampling/sampler.h"

#include <algorithm>
#include <cmath>

#include "sampling/hash.h"

namespace radiant {

namespace {

uint32_t reverse_bits(uint32_t v) {
  v = ((v >> 1) & 0x55555555U) | ((v & 0x55555555U) << 1);
  v = ((v >> 2) & 0x33333333U) | ((v & 0x33333333U) << 2);
  v = ((v >> 4) & 0x0F0F0F0FU) | ((v & 0x0F0F0F0FU) << 4);
  v = ((v >> 8) & 0x00FF00FFU) | ((v & 0x00FF00FFU) << 8);
  return (v >> 16) | (v << 16);
}

// Sobol dimension 1 generator columns (primitive polynomial x + 1: m_k = m_{k-1} ^ 2 m_{k-1}).
constexpr auto make_sobol_dimension1() {
  struct Columns {
    uint32_t v[32];
  } c{};
  uint32_t m = 1;
  for (int k = 0; k < 32; ++k) {
    c.v[k] = m << (31 - k);
    m = m ^ (m << 1);
  }
  return c;
}
constexpr auto sobol_dimension1 = make_sobol_dimension1();

uint32_t sobol_bits(uint32_t index, int dimension) {
  if (dimension == 0) return reverse_bits(index);
  uint32_t result = 0;
  for (int k = 0; index; ++k, index >>= 1)
    if (index & 1) result ^= sobol_dimension1.v[k];
  return result;
}

// Nested uniform scrambling approximated by a hash applied in bit-reversed order
// (Laine–Karras; the constants of Burley 2020 / pbrt-v4's FastOwenScrambler).
uint32_t owen_scramble(uint32_t v, uint32_t seed) {
  v = reverse_bits(v);
  v ^= v * 0x3d20adeaU;
  v += seed;
  v *= (seed >> 16) | 1;
  v ^= v * 0x05526c56U;
  v ^= v * 0x53a22864U;
  return reverse_bits(v);
}

// Element i of a pseudo-random permutation of [0, length) chosen by `seed` (Kensler 2013).
uint32_t permutation_element(uint32_t i, uint32_t length, uint32_t seed) {
  if (length <= 1) return 0;
  uint32_t w = length - 1;
  w |= w >> 1, w |= w >> 2, w |= w >> 4, w |= w >> 8, w |= w >> 16;
  do {
    i ^= seed, i *= 0xe170893dU, i ^= seed >> 16, i ^= (i & w) >> 4, i ^= seed >> 8, i *= 0x0929eb3fU;
    i ^= seed >> 23, i ^= (i & w) >> 1, i *= 1 | seed >> 27, i *= 0x6935fa69U, i ^= (i & w) >> 11;
    i *= 0x74dcb303U, i ^= (i & w) >> 2, i *= 0x9e501cc3U, i ^= (i & w) >> 2, i *= 0xc860a3dfU;
    i &= w, i ^= i >> 5;
  } while (i >= length);
  return (i + seed) % length;
}

// Padded Sobol (as pbrt-v4's PaddedSobolSampler): each pair of dimensions is the first two
// Sobol dimensions, Owen-scrambled and with the sample index permuted by its own seed, so that
// pairs are not correlated with each other (the pixel pair keeps the unpermuted order, which
// makes every prefix of the samples well spread for progressive and adaptive rendering).
struct PaddedSobolPair {
  uint32_t index, scramble;
};
PaddedSobolPair padded_sobol_pair(const SampleContext& c, uint32_t dimension) {
  uint32_t scramble = hash3(c.pixel, dimension, c.seed);
  uint32_t index = dimension == 0 ? c.index
                                  : permutation_element(c.index, std::max(c.samples, c.index + 1), mix_bits(scramble ^ 0x9e37u));
  return {index, scramble};
}

float random_value(const SampleContext& c, uint32_t dimension) {
  return bits_to_unit_float(hash4(c.pixel, c.index, dimension, c.seed));
}

// Strata for grid/jittered: nx * ny cells with nx * ny >= samples, as square as possible.
void strata(uint32_t samples, uint32_t& nx, uint32_t& ny) {
  nx = uint32_t(std::ceil(std::sqrt(double(samples))));
  ny = (samples + nx - 1) / nx;
}

}  // namespace

float sobol_scrambled(uint32_t index, int sobol_dimension, uint32_t seed) {
  return bits_to_unit_float(owen_scramble(sobol_bits(index, sobol_dimension), seed));
}

vec2 sample_pixel(const SampleContext& c) {
  switch (c.kind) {
    case SamplerKind::grid:
    case SamplerKind::jittered: {
      if (c.samples <= 1) return {0.5f, 0.5f};
      uint32_t nx, ny;
      strata(c.samples, nx, ny);
      // Strata in a per-pixel random order, so that the first k samples of a render stopped
      // early (time limit, noise threshold) are spread over the pixel, not its top rows. The
      // jitter belongs to the stratum, so the full set of positions does not depend on the order.
      uint32_t cells = nx * ny;
      uint32_t cell = permutation_element(c.index % cells, cells, hash3(c.pixel, c.seed, 0x5354u));
      vec2 offset = {0.5f, 0.5f};
      if (c.kind == SamplerKind::jittered)
        offset = {bits_to_unit_float(hash4(c.pixel, cell, 0, c.seed)), bits_to_unit_float(hash4(c.pixel, cell, 1, c.seed))};
      return {(float(cell % nx) + offset.x) / float(nx), (float(cell / nx) + offset.y) / float(ny)};
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
  PaddedSobolPair p = padded_sobol_pair(c, dimension);
  return sobol_scrambled(p.index, 0, p.scramble);
}

vec2 sample_2d(const SampleContext& c, uint32_t dimension) {
  if (c.kind != SamplerKind::sobol) return {random_value(c, dimension), random_value(c, dimension + 1)};
  PaddedSobolPair p = padded_sobol_pair(c, dimension);
  return {sobol_scrambled(p.index, 0, p.scramble), sobol_scrambled(p.index, 1, mix_bits(p.scramble))};
}

}  // namespace radiant
