// ExactSum: the same bits for every order and grouping of the terms, and the exact sum (rounded
// once) when the terms lie within the window of the largest.
#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "film/exact_sum.h"

using namespace radiant;

namespace {

// Values chosen to break floating-point associativity: tiny and huge, subnormal, cancelling pairs.
std::vector<double> adversarial_terms() {
  double float_max = std::numeric_limits<float>::max();
  std::vector<double> terms = {1e-300, 3e38, -3e38, 1.0, -1.0, std::numeric_limits<double>::denorm_min(),
                               0.1, 1e20, -1e20, 1e-20, float_max * float_max, -float_max * float_max,
                               5e-324, 1e308, -1e308, 7.25, 2.0e-5, 123456789.125};
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> exponent(-60, 60);
  for (int i = 0; i < 200; ++i) terms.push_back(std::ldexp(unit(random), exponent(random)));
  return terms;
}

// The terms summed in `groups` pieces (consecutive, random sizes), merged in a random order.
ExactSum grouped_sum(std::vector<double> terms, std::mt19937& random) {
  std::shuffle(terms.begin(), terms.end(), random);
  std::vector<ExactSum> pieces(1 + random() % 9);
  for (double t : terms) pieces[random() % pieces.size()].add(t);
  std::shuffle(pieces.begin(), pieces.end(), random);
  ExactSum total;
  for (const ExactSum& piece : pieces) total.add(piece);
  return total;
}

}  // namespace

TEST_CASE("exact sum: every order and grouping of adversarial terms gives the same state and value") {
  std::vector<double> terms = adversarial_terms();
  ExactSum in_order;
  for (double t : terms) in_order.add(t);
  std::mt19937 random(2024);
  for (int trial = 0; trial < 300; ++trial) {
    ExactSum other = grouped_sum(terms, random);
    REQUIRE(other == in_order);
    REQUIRE(std::bit_cast<uint64_t>(other.value()) == std::bit_cast<uint64_t>(in_order.value()));
  }
}

TEST_CASE("exact sum: float samples from 2^-20 to 1 sum exactly, rounded once to a double") {
  std::mt19937 random(3);
  std::uniform_real_distribution<float> unit(std::ldexp(1.0f, -20), 1.0f);
  ExactSum sum;
  __int128 exact = 0;  // in units of 2^-64: every such float is a whole number of them
  for (int i = 0; i < 100000; ++i) {
    float sample = unit(random);
    sum.add(sample);
    exact += __int128(std::ldexp(double(sample), 64));
  }
  CHECK(sum.value() == std::ldexp(double(exact), -64));
  // The plain double sum of the same samples in this order is not exact: that is the point.
}

TEST_CASE("exact sum: cancelling terms leave exactly the rest, in either order") {
  ExactSum a, b;
  for (double t : {1e30, 0.75, -1e30}) a.add(t);
  for (double t : {-1e30, 1e30, 0.75}) b.add(t);
  CHECK(a == b);
  // 0.75 lies 100 bits below 1e30, outside the window that 1e30 fixes: dropped in both orders.
  CHECK(a.value() == 0.0);
  ExactSum near;
  for (double t : {3.0, 0.75, -3.0}) near.add(t);
  CHECK(near.value() == 0.75);
}

TEST_CASE("exact sum: terms far below the largest are dropped alike before and after it arrives") {
  ExactSum small_first, large_first;
  small_first.add(1.0);
  small_first.add(std::ldexp(1.0, 64));
  large_first.add(std::ldexp(1.0, 64));
  large_first.add(1.0);
  CHECK(small_first == large_first);
  CHECK(small_first.value() == std::ldexp(1.0, 64));
  // 32 bits below the largest term's leading bit are always kept. 2^46 sits at the bottom of its
  // bin (position 1120 of the scale, 2^-1074 being 0): the worst case, where the 33rd goes.
  ExactSum kept, dropped;
  kept.add(std::ldexp(1.0, 46));
  kept.add(std::ldexp(1.0, 14));
  CHECK(kept.value() == std::ldexp(1.0, 46) + std::ldexp(1.0, 14));
  dropped.add(std::ldexp(1.0, 46));
  dropped.add(std::ldexp(1.0, 13));
  CHECK(dropped.value() == std::ldexp(1.0, 46));
}

TEST_CASE("exact sum: subnormals, the largest double and zero") {
  ExactSum tiny;
  for (int i = 0; i < 1000; ++i) tiny.add(std::numeric_limits<double>::denorm_min());
  CHECK(tiny.value() == 1000 * std::numeric_limits<double>::denorm_min());
  ExactSum huge, single;
  huge.add(std::numeric_limits<double>::max());
  huge.add(-std::numeric_limits<double>::max());
  huge.add(std::numeric_limits<double>::max());
  single.add(std::numeric_limits<double>::max());
  CHECK(huge == single);  // the cancelling pair leaves exactly the third term
  // Its leading bit is 49 positions above the window's lowest: the last 3 of its 53 bits go.
  CHECK(huge.value() == std::numeric_limits<double>::max() - std::ldexp(7.0, 971));
  ExactSum zero;
  zero.add(0.0);
  zero.add(-0.0);
  CHECK(zero == ExactSum());
  CHECK(zero.top() == ExactSum::empty_top);
  CHECK(zero.value() == 0.0);
}

TEST_CASE("exact sum: 2^24 terms of the largest float squared fit without overflow") {
  double square = double(std::numeric_limits<float>::max()) * std::numeric_limits<float>::max();
  ExactSum total;
  total.add(square);
  for (int doubling = 0; doubling < 24; ++doubling) {  // 2, 4, ... 2^24 terms
    ExactSum copy = total;
    total.add(copy);
  }
  CHECK(total.value() == std::ldexp(square, 24));
}

TEST_CASE("exact sum: a stored state comes back, states no sum reaches are refused") {
  ExactSum sum;
  for (double t : adversarial_terms()) sum.add(t);
  ExactSum back;
  REQUIRE(ExactSum::from_state(sum.top(), sum.high(), sum.low(), back));
  CHECK(back == sum);
  ExactSum refused;
  int64_t limit = int64_t(ExactSum::max_terms) * 0xffffffff;  // each term adds less than 2^32 a bin
  CHECK_FALSE(ExactSum::from_state(ExactSum::max_top + 1, 0, 0, refused));
  CHECK_FALSE(ExactSum::from_state(-1, 0, 0, refused));
  CHECK_FALSE(ExactSum::from_state(3, limit + 1, 0, refused));
  CHECK_FALSE(ExactSum::from_state(3, 0, -limit - 1, refused));
  CHECK_FALSE(ExactSum::from_state(ExactSum::empty_top, 1, 0, refused));
  CHECK(ExactSum::from_state(3, limit, -limit, refused));
  // A pixel of two samples cannot hold more than two terms' worth; one of none holds nothing.
  CHECK(ExactSum::from_state(3, 2 * 0xffffffffll, 0, refused, 2));
  CHECK_FALSE(ExactSum::from_state(3, 2 * 0xffffffffll + 1, 0, refused, 2));
  CHECK_FALSE(ExactSum::from_state(3, 0, 0, refused, 0));
  CHECK_FALSE(ExactSum::from_state(3, 0, 0, refused, ExactSum::max_terms + 1));
}

TEST_CASE("exact sum: the value is the window rounded once, at every window position") {
  // value() scales by a power of two it builds itself where that power is a double, and by ldexp
  // below: both must round the window as ldexp does, across the subnormal and normal ranges.
  std::mt19937 random(11);
  std::uniform_int_distribution<int64_t> bin(-int64_t(ExactSum::max_terms) * 0xffffffff,
                                             int64_t(ExactSum::max_terms) * 0xffffffff);
  for (int top = 0; top <= ExactSum::max_top; ++top)
    for (int trial = 0; trial < 64; ++trial) {
      int64_t high = trial == 0 ? 0 : bin(random), low = trial == 1 ? 1 : bin(random);
      if (trial == 2) high = 1, low = -1;  // the smallest positive window: 2^32 - 1 lowest positions
      ExactSum sum;
      REQUIRE(ExactSum::from_state(top, high, low, sum));
      __int128 window = (__int128(high) << ExactSum::bin_bits) + low;
      double expected = std::ldexp(double(window), ExactSum::bin_bits * (top - 1) - 1074);
      CAPTURE(top);
      CAPTURE(trial);
      CHECK(std::bit_cast<uint64_t>(sum.value()) == std::bit_cast<uint64_t>(expected));
    }
}
