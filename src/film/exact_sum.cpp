#include "film/exact_sum.h"

#include <cmath>

namespace radiant {

double ExactSum::value() const {
  if (top() == empty_top) return 0;
  // Both bins as one integer (below 2^89 in magnitude), in units of the window's lowest position;
  // position 0 is 2^-1074.
  __int128 window = (__int128(high_) << bin_bits) + low();
  // Scaling by a power of two that is itself a double rounds once, exactly as ldexp does, for a
  // fraction of its cost (the film reads every pixel's sums after each render). Only windows
  // whose lowest position lies below 2^-1074 (sums of subnormals) need ldexp.
  int exponent = bin_bits * (top() - 1) - 1074;
  if (exponent < -1074) return std::ldexp(double(window), exponent);
  uint64_t power_bits = exponent >= -1022 ? uint64_t(exponent + 1023) << 52 : uint64_t(1) << (exponent + 1074);
  return double(window) * std::bit_cast<double>(power_bits);
}

bool ExactSum::from_state(int top, int64_t high, int64_t low, ExactSum& sum, uint32_t terms) {
  if (terms > max_terms) return false;
  int64_t bin_limit = int64_t(terms) * 0xffffffff;
  if (top == empty_top || terms == 0) {
    if (top != empty_top || high != 0 || low != 0) return false;
  } else if (top < 0 || top > max_top || high < -bin_limit || high > bin_limit || low < -bin_limit ||
             low > bin_limit) {
    return false;
  }
  sum.high_ = high;
  sum.low_and_top_ = low * top_scale + top;
  return true;
}

}  // namespace radiant
