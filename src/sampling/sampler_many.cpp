#include "sampling/sampler.h"
#include "sampling/sobol.h"

namespace radiant {

namespace {

// The same inline functions as sample_2d, run across the lanes. GCC compiles the loop twice and
// picks at load time: AVX2 has 32-bit multiplies and byte shuffles for eight lanes; the SSE2
// baseline emulates the multiplies over four.
[[gnu::target_clones("avx2", "default")]] void sobol_pairs(const uint32_t* __restrict pixel,
                                                            const uint32_t* __restrict index,
                                                            const uint32_t* __restrict dimension,
                                                            const uint32_t* __restrict seed, int count,
                                                            float* __restrict x, float* __restrict y) {
  for (int i = 0; i < count; ++i) {
    sobol::ShuffledIndex s = sobol::shuffle(pixel[i], index[i], dimension[i], seed[i]);
    x[i] = bits_to_unit_float(sobol::x_bits(s));
    y[i] = bits_to_unit_float(sobol::y_bits(s));
  }
}

}  // namespace

void draw_sobol_lanes(SobolLanes& lanes) {
  sobol_pairs(lanes.pixel, lanes.index, lanes.dimension, lanes.seed, lanes.count, lanes.x, lanes.y);
}

}  // namespace radiant
