#include "sampling/sampler.h"

#include <algorithm>
#include <cmath>

#include "math/fast_divisor.h"
#include "sampling/hash.h"
#include "sampling/hashed_value.h"
#include "sampling/sobol.h"
#include "sampling/strata.h"

namespace radiant {

namespace {

float random_value(const SampleContext& c, uint32_t dimension) {
  return hashed_value(c.pixel, c.index, dimension, c.seed);
}

}  // namespace

const Strata& strata(uint32_t samples) {
  thread_local Strata s;
  if (s.samples != samples) {
    uint32_t nx = uint32_t(std::ceil(std::sqrt(double(samples))));
    uint32_t ny = (samples + nx - 1) / nx;
    s = {samples, FastDivisor(nx), FastDivisor(ny), FastDivisor(nx * ny)};
  }
  return s;
}

vec2 sample_pixel(const SampleContext& c) {
  switch (c.kind) {
    case SamplerKind::grid:
    case SamplerKind::jittered: {
      if (c.samples <= 1) return {0.5f, 0.5f};
      const Strata& grid = strata(c.samples);
      // Strata in a per-pixel random order, so that the first k samples of a render stopped
      // early (time limit, noise threshold) are spread over the pixel, not its top rows. The
      // jitter belongs to the stratum, so the full set of positions does not depend on the order.
      uint32_t order_seed = hash3(c.pixel, c.seed, strata_order_seed_salt);
      uint32_t cell = permutation_element(grid.cells.remainder(c.index), grid.cells, order_seed);
      vec2 offset = {0.5f, 0.5f};
      if (c.kind == SamplerKind::jittered)
        offset = {hashed_value(c.pixel, cell, 0, c.seed), hashed_value(c.pixel, cell, 1, c.seed)};
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

float sample_time(const SampleContext& c) {
  if (c.kind == SamplerKind::sobol || c.kind == SamplerKind::random || c.samples <= 1) return sample_1d(c, time_dimension);
  // Its own order of strata, so that the time does not follow the pixel position's stratum.
  FastDivisor strata_count(c.samples);
  uint32_t order_seed = hash3(c.pixel, c.seed, time_dimension);
  uint32_t stratum = permutation_element(strata_count.remainder(c.index), strata_count, order_seed);
  float offset = c.kind == SamplerKind::jittered ? hashed_value(c.pixel, c.index, time_dimension, c.seed) : 0.5f;
  return std::min((float(stratum) + offset) / float(c.samples), 0x1.fffffep-1f);
}

vec2 sample_2d(const SampleContext& c, uint32_t dimension) {
  if (c.kind != SamplerKind::sobol) return {random_value(c, dimension), random_value(c, dimension + 1)};
  sobol::ShuffledIndex s = sobol::shuffle(c.pixel, c.index, dimension, c.seed);
  return {bits_to_unit_float(sobol::x_bits(s)), bits_to_unit_float(sobol::y_bits(s))};
}

}  // namespace radiant
