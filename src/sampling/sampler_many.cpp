#include "sampling/sampler.h"

#include <algorithm>

#include "sampling/hash.h"
#include "sampling/hashed_value.h"
#include "sampling/sobol.h"
#include "sampling/strata.h"

namespace radiant {

namespace {

// The same inline functions as sample_2d, run across the lanes (math/lane_isa.h): eight at a
// time with AVX2's 32-bit multiplies and byte shuffles. The SSE2 baseline keeps the loop scalar:
// GCC vectorises the bit reversal's byte swap only with SSSE3's byte shuffle.
[[gnu::always_inline]] inline void sobol_pairs(const uint32_t* __restrict pixel, const uint32_t* __restrict index,
                                               const uint32_t* __restrict dimension, const uint32_t* __restrict seed,
                                               int count, float* __restrict x, float* __restrict y) {
  for (int i = 0; i < count; ++i) {
    sobol::ShuffledIndex s = sobol::shuffle(pixel[i], index[i], dimension[i], seed[i]);
    x[i] = bits_to_unit_float(sobol::x_bits(s));
    y[i] = bits_to_unit_float(sobol::y_bits(s));
  }
}

[[gnu::target("avx2")]] void sobol_pairs_avx2(SampleLanes& l) {
  sobol_pairs(l.pixel, l.index, l.dimension, l.seed, l.count, l.x, l.y);
}
void sobol_pairs_baseline(SampleLanes& l) { sobol_pairs(l.pixel, l.index, l.dimension, l.seed, l.count, l.x, l.y); }

// The other samplers' pairs, sample_2d's two hashes per lane: eight at a time with AVX2, four
// with SSE2 (which GCC gives 32-bit multiplies made of its 64-bit ones).
[[gnu::always_inline]] inline void hashed_pairs(const uint32_t* __restrict pixel, const uint32_t* __restrict index,
                                                const uint32_t* __restrict dimension, const uint32_t* __restrict seed,
                                                int count, float* __restrict x, float* __restrict y) {
  for (int i = 0; i < count; ++i) {
    x[i] = hashed_value(pixel[i], index[i], dimension[i], seed[i]);
    y[i] = hashed_value(pixel[i], index[i], dimension[i] + 1, seed[i]);
  }
}

[[gnu::target("avx2")]] void hashed_pairs_avx2(SampleLanes& l) {
  hashed_pairs(l.pixel, l.index, l.dimension, l.seed, l.count, l.x, l.y);
}
void hashed_pairs_baseline(SampleLanes& l) { hashed_pairs(l.pixel, l.index, l.dimension, l.seed, l.count, l.x, l.y); }

// sample_pixel's grid and jittered branch across the lanes, loop by loop: the hashes, the
// permutation's rounds and the final arithmetic vectorise; the divisor's 128-bit products stay
// scalar. A permutation walks again while its value lies outside the cells (Kensler's cycle
// walking): every lane takes the round and keeps it only where it was outside, so the lanes
// stay in step. At most `stratified_chunk` lanes.
constexpr int stratified_chunk = 64;

[[gnu::always_inline]] inline void stratified_pixels(bool jittered, const Strata& grid, uint32_t index, uint32_t seed,
                                                     const uint32_t* __restrict pixel, int count,
                                                     float* __restrict x, float* __restrict y) {
  uint32_t order_seed[stratified_chunk], cell[stratified_chunk];
  float column[stratified_chunk], row[stratified_chunk];
  const uint32_t length = grid.cells.d, mask = permutation_mask(length), first = grid.cells.remainder(index);
  for (int i = 0; i < count; ++i) order_seed[i] = hash3(pixel[i], seed, strata_order_seed_salt);
  for (int i = 0; i < count; ++i) cell[i] = permutation_round(first, order_seed[i], mask);
  for (;;) {
    uint32_t outside = 0;
    for (int i = 0; i < count; ++i) outside |= uint32_t(cell[i] >= length);
    if (!outside) break;
    for (int i = 0; i < count; ++i) {
      uint32_t again = permutation_round(cell[i], order_seed[i], mask);
      cell[i] = cell[i] >= length ? again : cell[i];
    }
  }
  for (int i = 0; i < count; ++i) {
    cell[i] = grid.cells.remainder(cell[i] + order_seed[i]);
    column[i] = float(grid.nx.remainder(cell[i]));
    row[i] = float(grid.nx.quotient(cell[i]));
  }
  const float width = float(grid.nx.d), height = float(grid.ny.d);
  if (jittered) {
    for (int i = 0; i < count; ++i) {
      x[i] = (column[i] + hashed_value(pixel[i], cell[i], 0, seed)) / width;
      y[i] = (row[i] + hashed_value(pixel[i], cell[i], 1, seed)) / height;
    }
  } else {
    for (int i = 0; i < count; ++i) x[i] = (column[i] + 0.5f) / width, y[i] = (row[i] + 0.5f) / height;
  }
}

[[gnu::target("avx2")]] void stratified_pixels_avx2(bool jittered, const Strata& grid, uint32_t index, uint32_t seed,
                                                    const uint32_t* pixel, int count, float* x, float* y) {
  stratified_pixels(jittered, grid, index, seed, pixel, count, x, y);
}
void stratified_pixels_baseline(bool jittered, const Strata& grid, uint32_t index, uint32_t seed,
                                const uint32_t* pixel, int count, float* x, float* y) {
  stratified_pixels(jittered, grid, index, seed, pixel, count, x, y);
}

}  // namespace

void draw_stratified_pixels(SamplerKind kind, uint32_t samples, uint32_t index, uint32_t seed, const uint32_t* pixel,
                            int count, float* x, float* y, LaneIsa isa) {
  if (samples <= 1) {  // one sample shoots through the centre
    std::fill(x, x + count, 0.5f);
    std::fill(y, y + count, 0.5f);
    return;
  }
  const Strata& grid = strata(samples);
  bool jittered = kind == SamplerKind::jittered, avx2 = resolve_lane_isa(isa) == LaneIsa::avx2;
  for (int begin = 0; begin < count; begin += stratified_chunk) {
    int n = std::min(stratified_chunk, count - begin);
    if (avx2)
      stratified_pixels_avx2(jittered, grid, index, seed, pixel + begin, n, x + begin, y + begin);
    else
      stratified_pixels_baseline(jittered, grid, index, seed, pixel + begin, n, x + begin, y + begin);
  }
}

void draw_sample_lanes(SamplerKind kind, SampleLanes& lanes, LaneIsa isa) {
  bool avx2 = resolve_lane_isa(isa) == LaneIsa::avx2;
  if (kind == SamplerKind::sobol)
    avx2 ? sobol_pairs_avx2(lanes) : sobol_pairs_baseline(lanes);
  else
    avx2 ? hashed_pairs_avx2(lanes) : hashed_pairs_baseline(lanes);
}

}  // namespace radiant
