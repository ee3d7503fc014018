// Exact remainder and quotient of a 32-bit value by a divisor fixed in advance, by two
// multiplications instead of a division (Lemire, Kaser and Kurz 2019, "Faster remainder by
// direct computation"): a division costs tens of cycles, and samplers divide per sample.
#pragma once

#include <cstdint>

namespace radiant {

struct FastDivisor {
  uint32_t d = 1;
  uint64_t m = 0;  // ceil(2^64 / d); wraps to 0 for d = 1, for which both results still hold

  // `divisor` must not be 0.
  explicit FastDivisor(uint32_t divisor = 1) : d(divisor), m(UINT64_C(0xFFFFFFFFFFFFFFFF) / divisor + 1) {}
  // a % d, for every 32-bit a.
  uint32_t remainder(uint32_t a) const { return uint32_t((unsigned __int128)(m * a) * d >> 64); }
  // a / d, for every 32-bit a.
  uint32_t quotient(uint32_t a) const { return d == 1 ? a : uint32_t((unsigned __int128)m * a >> 64); }
};

}  // namespace radiant
