#include "sampling/sampler.h"
#include "sampling/sobol.h"

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

[[gnu::target("avx2")]] void sobol_pairs_avx2(SobolLanes& l) {
  sobol_pairs(l.pixel, l.index, l.dimension, l.seed, l.count, l.x, l.y);
}
void sobol_pairs_baseline(SobolLanes& l) { sobol_pairs(l.pixel, l.index, l.dimension, l.seed, l.count, l.x, l.y); }

}  // namespace

void draw_sobol_lanes(SobolLanes& lanes, LaneIsa isa) {
  if (resolve_lane_isa(isa) == LaneIsa::avx2)
    sobol_pairs_avx2(lanes);
  else
    sobol_pairs_baseline(lanes);
}

}  // namespace radiant
