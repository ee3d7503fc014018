#include "sampling/sampler.h"

#include <algorithm>
#include <cmath>

#include "math/fast_divisor.h"
#include "sampling/hash.h"
#include "sampling/sobol.h"

namespace radiant {

namespace {

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
  return bits_to_unit_float(sobol::x_bits(sobol::shuffle(c.pixel, c.index, dimension, c.seed)));
}

vec2 sample_2d(const SampleContext& c, uint32_t dimension) {
  if (c.kind != SamplerKind::sobol) return {random_value(c, dimension), random_value(c, dimension + 1)};
  sobol::ShuffledIndex s = sobol::shuffle(c.pixel, c.index, dimension, c.seed);
  return {bits_to_unit_float(sobol::x_bits(s)), bits_to_unit_float(sobol::y_bits(s))};
}

}  // namespace radiant
