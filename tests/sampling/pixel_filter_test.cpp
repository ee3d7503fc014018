// Pixel filters by importance sampling: each filter's samples follow its density (chi-square, as
// the BSDF tests), that density is the filter's shape, and the weights f / pdf average to 1.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "sampling/pixel_filter.h"
#include "support/chi_square.h"

using namespace radiant;
using namespace radiant::test;

namespace {

const PixelFilterKind all_filters[] = {PixelFilterKind::box, PixelFilterKind::triangle, PixelFilterKind::gaussian,
                                       PixelFilterKind::mitchell, PixelFilterKind::blackman_harris};

// The integral of |f| (or f) over [a, b] by the midpoint rule on 4096 steps.
double integrate_filter(PixelFilterKind kind, float radius, double a, double b, bool magnitude) {
  constexpr int steps = 4096;
  double h = (b - a) / steps, sum = 0;
  for (int i = 0; i < steps; ++i) {
    double f = eval_filter_1d(kind, radius, float(a + (i + 0.5) * h));
    sum += magnitude ? std::abs(f) : f;
  }
  return sum * h;
}

// The integral of sample_filter_pdf_1d over [a, b] (4096 midpoints: a table's cell edges fall
// between them).
double integrate_pdf(const PixelFilter& filter, double a, double b) {
  constexpr int steps = 4096;
  double h = (b - a) / steps, sum = 0;
  for (int i = 0; i < steps; ++i) sum += sample_filter_pdf_1d(filter, float(a + (i + 0.5) * h));
  return sum * h;
}

}  // namespace

TEST_CASE("pixel filter: each filter's samples follow its density over the pixel's neighbourhood (chi-square, 2D)") {
  constexpr int bins = 20, sample_count = 400000;
  double corrected = 1 - std::pow(1 - 0.01, 1.0 / std::size(all_filters));  // Sidak
  for (PixelFilterKind kind : all_filters) {
    PixelFilter filter = make_pixel_filter(kind, default_filter_radius(kind));
    CAPTURE(pixel_filter_name(kind));
    float r = filter.radius;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> uniform(0.0f, std::nextafter(1.0f, 0.0f));
    std::vector<double> observed(bins * bins, 0.0), expected(bins * bins, 0.0), axis(bins);
    for (int i = 0; i < sample_count; ++i) {
      FilterSample s = sample_filter(filter, {uniform(rng), uniform(rng)});
      // Offsets from the pixel centre, in [-r, r].
      float x = s.position.x - 0.5f, y = s.position.y - 0.5f;
      REQUIRE(std::abs(x) <= r);
      REQUIRE(std::abs(y) <= r);
      // (A sample on the radius itself, rounded there, counts in the last bin.)
      int bx = std::min(bins - 1, int((x + r) / (2 * r) * bins)), by = std::min(bins - 1, int((y + r) / (2 * r) * bins));
      observed[size_t(by) * bins + size_t(bx)] += 1;
    }
    for (int b = 0; b < bins; ++b) axis[size_t(b)] = integrate_pdf(filter, -r + 2.0 * r * b / bins, -r + 2.0 * r * (b + 1) / bins);
    for (int by = 0; by < bins; ++by)
      for (int bx = 0; bx < bins; ++bx) expected[size_t(by) * bins + size_t(bx)] = axis[size_t(bx)] * axis[size_t(by)] * sample_count;
    double p_value = 0;
    CHECK(chi_square_test(observed, expected, sample_count, 5, p_value) == "");
    INFO("p-value = ", p_value);
    CHECK(p_value > corrected);
  }
}

TEST_CASE("pixel filter: the sampling density is the filter's |f| over its integral (tabulated at 32 cells a pixel)") {
  for (PixelFilterKind kind : all_filters) {
    CAPTURE(pixel_filter_name(kind));
    for (float width : {1.0f, 3.0f, 4.0f}) {
      CAPTURE(width);
      float r = width / 2;
      PixelFilter filter = make_pixel_filter(kind, r);
      double total = integrate_filter(kind, r, -r, r, true);
      CHECK(integrate_pdf(filter, -r, r) == doctest::Approx(1).epsilon(1e-3));
      int cells = int(32 * r);
      for (int i = 0; i < cells; i += 3) {
        float centre = -r + 2 * r * (i + 0.5f) / cells;  // where a table holds the filter exactly
        CHECK(sample_filter_pdf_1d(filter, centre) * total ==
              doctest::Approx(std::abs(eval_filter_1d(kind, r, centre))).epsilon(0.01).scale(0.01));
      }
      CHECK(sample_filter_pdf_1d(filter, r * 1.01f) == 0);
    }
  }
}

TEST_CASE("pixel filter: weights average to 1 with one magnitude per filter, only Mitchell's lobes are negative") {
  for (PixelFilterKind kind : all_filters) {
    CAPTURE(pixel_filter_name(kind));
    PixelFilter filter = make_pixel_filter(kind, default_filter_radius(kind));
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> uniform(0.0f, std::nextafter(1.0f, 0.0f));
    constexpr int n = 200000;
    double sum = 0;
    int negative = 0;
    float magnitude = std::abs(sample_filter(filter, {0.5f, 0.5f}).weight);
    for (int i = 0; i < n; ++i) {
      float w = sample_filter(filter, {uniform(rng), uniform(rng)}).weight;
      sum += w;
      negative += w < 0;
      REQUIRE(std::abs(w) == magnitude);
    }
    CHECK(sum / n == doctest::Approx(1).epsilon(0.01));
    if (kind == PixelFilterKind::mitchell) {
      CHECK(negative > 0);
      // The negative lobes' share: sum |f| / sum f = 1 / (1 - 2 m) per axis.
      double r = filter.radius, m_axis = (1 - integrate_filter(kind, filter.radius, -r, r, false) /
                                                  integrate_filter(kind, filter.radius, -r, r, true)) / 2;
      CHECK(magnitude == doctest::Approx(1 / ((1 - 2 * m_axis) * (1 - 2 * m_axis))).epsilon(1e-3));
    } else {
      CHECK(negative == 0);
      CHECK(magnitude == 1);
    }
  }
}

TEST_CASE("pixel filter: the default box of one pixel places a sample at the sampler's own position, so images do not move") {
  PixelFilter box = make_pixel_filter(PixelFilterKind::box, 0.5f);
  for (float x : {0.0f, 1e-7f, 0.1f, 0.3333333f, 0.5f, 0.99999994f})
    for (float y : {0.0f, 0.25f, 0.7f}) {
      FilterSample s = sample_filter(box, {x, y});
      CHECK(s.position.x == x);
      CHECK(s.position.y == y);
      CHECK(s.weight == 1);
    }
}

TEST_CASE("pixel filter: names parse back, and a width not above 0 or above 64 pixels is refused") {
  for (PixelFilterKind kind : all_filters) CHECK(parse_pixel_filter(pixel_filter_name(kind)) == kind);
  CHECK_THROWS_WITH_AS(parse_pixel_filter("lanczos"),
                       "unknown filter 'lanczos' (box, triangle, gaussian, mitchell or blackman-harris)", std::invalid_argument);
  CHECK_THROWS_AS(make_pixel_filter(PixelFilterKind::gaussian, 0), std::invalid_argument);
  CHECK_THROWS_AS(make_pixel_filter(PixelFilterKind::gaussian, 33), std::invalid_argument);
  CHECK_THROWS_AS(make_pixel_filter(PixelFilterKind::gaussian, std::nanf("")), std::invalid_argument);
  CHECK(default_filter_radius(PixelFilterKind::box) == 0.5f);
  CHECK(default_filter_radius(PixelFilterKind::triangle) == 2);
  CHECK(default_filter_radius(PixelFilterKind::gaussian) == 1.5f);
  CHECK(default_filter_radius(PixelFilterKind::mitchell) == 2);
  CHECK(default_filter_radius(PixelFilterKind::blackman_harris) == 2);
}
