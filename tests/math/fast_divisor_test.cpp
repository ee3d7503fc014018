// FastDivisor gives exactly a % d and a / d: for edge values of both, every divisor up to 300
// (the strata counts samplers use), and random pairs over the whole 32-bit range.
#include <doctest/doctest.h>

#include <cstdint>
#include <random>

#include "math/fast_divisor.h"

using namespace radiant;

namespace {

int mismatches(uint32_t d, uint32_t a) {
  FastDivisor f(d);
  return (f.remainder(a) != a % d) + (f.quotient(a) != a / d);
}

}  // namespace

TEST_CASE("fast divisor: remainder and quotient are exact for edge values, small divisors and random pairs") {
  const uint32_t edges[] = {0u, 1u, 2u, 3u, 7u, 80u, 81u, 82u, 255u, 256u, 65535u, 65536u, 0x7FFFFFFFu,
                            0x80000000u, 0x80000001u, 0xFFFFFFFEu, 0xFFFFFFFFu};
  int wrong = 0;
  for (uint32_t d : edges)
    if (d != 0)
      for (uint32_t a : edges) wrong += mismatches(d, a);
  for (uint32_t d = 1; d <= 300; ++d)
    for (uint32_t a = 0; a < 5000; ++a) wrong += mismatches(d, a) + mismatches(d, 0xFFFFFFFFu - a);
  std::mt19937 rng(11);
  for (int i = 0; i < 1000000; ++i) {
    uint32_t d = rng() >> (rng() % 32);
    wrong += mismatches(d == 0 ? 1 : d, rng());
  }
  CHECK(wrong == 0);
}
