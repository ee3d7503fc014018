// A sum of doubles that comes out the same, to the bit, for every order and grouping of its terms:
// a render, its tiles and its sample ranges (summed apart and merged later, docs/distributed.md)
// all give one result. Floating-point addition is not associative; integer addition is.
//
// A binned sum (after Demmel and Nguyen's reproducible summation): every bit of a double has a
// fixed position on one global scale, cut into bins of 32 positions. The sum keeps the two bins
// at and below the bin of its largest term (the window), each an integer holding the sum of
// every term's bits in that bin. A term's bits below the window are dropped. What is kept
// depends only on the terms (their largest fixes the window), never on their order: a term
// added before the window rose loses, when it rises, exactly the bits it would have lost after.
// The window keeps at least 32 bits below the largest term's leading bit, more than a float's
// 24: each term loses less than 2^-32 of the largest term, so a pixel's mean is off by less than
// 2^-32 * (its brightest sample / the mean), relative: within a float's rounding (2^-24) while
// no sample is more than 256 times the mean, and off by at most 2^-22 for a firefly 1024 times
// the mean. Any finite double
// is taken; the 2^24 terms of a pixel at most fit the bins without overflow (max_terms).
#pragma once

#include <bit>
#include <cstdint>

namespace radiant {

class ExactSum {
 public:
  static constexpr int bin_bits = 32;
  static constexpr uint32_t max_terms = 1u << 24;  // bins stay below 2^56 in magnitude
  static constexpr int empty_top = 127;           // the top bin of a sum of no nonzero term
  static constexpr int max_top = 65;              // the bin of the largest double's leading bit

  // Adds a finite value (an infinite or NaN one must never reach a sum).
  void add(double value) {
    uint64_t bits = std::bit_cast<uint64_t>(value);
    uint64_t mantissa = bits & ((uint64_t(1) << 52) - 1);
    int exponent = int((bits >> 52) & 0x7ff);
    if (exponent != 0) mantissa |= uint64_t(1) << 52;
    if (mantissa == 0) return;  // ±0 changes nothing, not even the window
    // Position of the mantissa's lowest bit on the global scale: 0 for the smallest subnormal.
    int lowest = exponent == 0 ? 0 : exponent - 1;
    int leading = lowest + 63 - std::countl_zero(mantissa);
    raise_window(leading / bin_bits);
    int shift = lowest - bin_bits * (top() - 1);  // from the window's lowest position
    uint64_t window_bits = shift >= 0 ? mantissa << shift : (-shift < 64 ? mantissa >> -shift : 0);
    int64_t high_part = int64_t(window_bits >> bin_bits), low_part = int64_t(window_bits & 0xffffffffu);
    if (bits >> 63) high_part = -high_part, low_part = -low_part;
    high_ += high_part;
    low_and_top_ += low_part * top_scale;
  }

  // Adds every term of `other` (merging shards).
  void add(const ExactSum& other) {
    if (other.top() == empty_top) return;
    raise_window(other.top());
    ExactSum aligned = other;
    aligned.raise_window(top());
    high_ += aligned.high_;
    low_and_top_ += aligned.low() * top_scale;
  }

  // The sum, rounded to a double (the same double for the same terms).
  double value() const;

  // The stored state, for shard files: the two bins and the window's top bin (empty_top when
  // empty). from_state refuses (returns false) a state no sum of `terms` terms can reach: every
  // term adds less than 2^32 to each bin, so that sums of states of up to max_terms terms in all
  // never overflow.
  int top() const { return int(low_and_top_ & (top_scale - 1)); }
  int64_t high() const { return high_; }
  int64_t low() const { return low_and_top_ >> 7; }
  static bool from_state(int top, int64_t high, int64_t low, ExactSum& sum, uint32_t terms = max_terms);

  bool operator==(const ExactSum&) const = default;

 private:
  // The low bin is stored shifted by 7 bits above the top bin's index: one sum is 16 bytes.
  static constexpr int64_t top_scale = 128;

  // Moves the window up so that its top bin is at least `bin`; bins that fall out are dropped.
  void raise_window(int bin) {
    int current = top();
    if (current != empty_top && bin <= current) return;
    int64_t low = current != empty_top && bin == current + 1 ? high_ : 0;
    high_ = 0;
    low_and_top_ = low * top_scale + bin;
  }

  int64_t high_ = 0;
  int64_t low_and_top_ = empty_top;
};

}  // namespace radiant
