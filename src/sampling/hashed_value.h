// The values of every sampler but Sobol: an independent hash of a sample's coordinates, for each
// dimension beyond the pixel position (the random sampler's pixel position too) and, with the
// stratum for the index, for the jitter inside a stratum. Shared by the one-sample functions
// and their lanes (sampler_many.cpp), which must agree to the bit.
#pragma once

#include <cstdint>

#include "sampling/hash.h"

namespace radiant {

[[gnu::always_inline]] inline float hashed_value(uint32_t pixel, uint32_t index, uint32_t dimension, uint32_t seed) {
  return bits_to_unit_float(hash4(pixel, index, dimension, seed));
}

}  // namespace radiant
