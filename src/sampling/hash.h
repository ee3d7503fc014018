// Stateless integer hashing: every random number in radiant is a pure function of its inputs.
#pragma once

#include <cstdint>

namespace radiant {

// A strong 32-bit mix (the "lowbias32" finalizer by Chris Wellons).
constexpr uint32_t mix_bits(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

constexpr uint32_t hash_combine(uint32_t seed, uint32_t value) {
  return mix_bits(seed ^ (value + 0x9e3779b9U + (seed << 6) + (seed >> 2)));
}

constexpr uint32_t hash4(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  return hash_combine(hash_combine(hash_combine(mix_bits(a), b), c), d);
}

// One mixing round over three values: cheap enough to run for every sample dimension.
constexpr uint32_t hash3(uint32_t a, uint32_t b, uint32_t c) {
  return mix_bits(a * 0x9e3779b1U ^ (b + 0x7f4a7c15U) * 0x85ebca77U ^ (c + 0x165667b1U) * 0xc2b2ae3dU);
}

// Maps 32 random bits to a float in [0, 1).
constexpr float bits_to_unit_float(uint32_t bits) { return float(bits >> 8) * 0x1p-24f; }

}  // namespace radiant
