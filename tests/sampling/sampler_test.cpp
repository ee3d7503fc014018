// Samplers: strata coverage, progressive prefixes, purity, and the pixel positions and Sobol pairs drawn in SIMD.
#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <set>
#include <vector>

#include "sampling/sampler.h"
#include "sampling/sobol.h"

using namespace radiant;

namespace {

SampleContext context(SamplerKind kind, uint32_t index, uint32_t samples, uint32_t pixel = 7) {
  return {kind, pixel, index, samples, 3};
}

std::pair<int, int> cell_of(vec2 p, int n) { return {int(p.x * n), int(p.y * n)}; }

}  // namespace

TEST_CASE("sampler: one sample per pixel goes through the centre for grid and jittered") {
  for (SamplerKind kind : {SamplerKind::grid, SamplerKind::jittered}) {
    vec2 p = sample_pixel(context(kind, 0, 1));
    CHECK(p.x == 0.5f);
    CHECK(p.y == 0.5f);
  }
}

TEST_CASE("sampler: grid and jittered put exactly one of 16 samples in each 4x4 stratum") {
  for (SamplerKind kind : {SamplerKind::grid, SamplerKind::jittered}) {
    std::set<std::pair<int, int>> cells;
    for (uint32_t i = 0; i < 16; ++i) cells.insert(cell_of(sample_pixel(context(kind, i, 16)), 4));
    CHECK(cells.size() == 16);
  }
}

TEST_CASE("sampler: the first samples of a stratified render are spread over the pixel, not its top rows") {
  // A render stopped early keeps only a prefix of the samples; raster-ordered strata would
  // put all of them in the top rows and bias the pixel.
  int top_half = 0, total = 0;
  for (uint32_t pixel = 0; pixel < 200; ++pixel)
    for (uint32_t i = 0; i < 8; ++i, ++total) top_half += sample_pixel(context(SamplerKind::jittered, i, 64, pixel)).y < 0.5f;
  CHECK(double(top_half) / total == doctest::Approx(0.5).epsilon(0.08));
}

TEST_CASE("sampler: the first 16 Sobol pixel samples form a (0,4,2)-net: one per 4x4 and per 16x1 cell") {
  std::set<std::pair<int, int>> square, columns;
  for (uint32_t i = 0; i < 16; ++i) {
    vec2 p = sample_pixel(context(SamplerKind::sobol, i, 64));
    square.insert(cell_of(p, 4));
    columns.insert({int(p.x * 16), 0});
  }
  CHECK(square.size() == 16);
  CHECK(columns.size() == 16);
}

TEST_CASE("sampler: 64 samples of a padded Sobol pair form a (0,6,2)-net in every pair, for any pixel") {
  // The index shuffle maps the first 64 indices onto one aligned block of 64 Sobol points.
  for (uint32_t pixel : {0u, 7u, 123456u})
    for (uint32_t dimension : {2u, 5u, 33u}) {
      CAPTURE(pixel);
      CAPTURE(dimension);
      std::set<std::pair<int, int>> square, columns, rows;
      for (uint32_t i = 0; i < 64; ++i) {
        vec2 p = sample_2d(context(SamplerKind::sobol, i, 64, pixel), dimension);
        square.insert(cell_of(p, 8));
        columns.insert({int(p.x * 64), 0});
        rows.insert({0, int(p.y * 64)});
      }
      CHECK(square.size() == 64);
      CHECK(columns.size() == 64);
      CHECK(rows.size() == 64);
    }
}

TEST_CASE("sampler: different Sobol pairs are not correlated with each other") {
  // Without a shuffle per pair, two pairs' first coordinates are scramblings of the same radical
  // inverse: plotted against each other, 256 samples would fill only 16 of the 16x16 cells.
  // Independent points fill about 162 of them.
  std::set<std::pair<int, int>> cells;
  for (uint32_t i = 0; i < 256; ++i) {
    SampleContext c = context(SamplerKind::sobol, i, 256);
    cells.insert(cell_of({sample_1d(c, 2), sample_1d(c, 12)}, 16));
  }
  CHECK(cells.size() > 130);
}

TEST_CASE("sampler: every value is a pure function of (pixel, index, dimension, seed) inside the unit interval") {
  for (SamplerKind kind : {SamplerKind::random, SamplerKind::jittered, SamplerKind::sobol}) {
    for (uint32_t i = 0; i < 32; ++i) {
      SampleContext c = context(kind, i, 32);
      vec2 a = sample_2d(c, 5), b = sample_2d(c, 5);
      CHECK(a.x == b.x);
      CHECK(a.y == b.y);
      float v = sample_1d(c, 9);
      CHECK(v >= 0.0f);
      CHECK(v < 1.0f);
    }
  }
}

TEST_CASE("sampler: the strata follow the sample count when it changes between samples of one thread") {
  // The strata are worked out once per count; a different count must not reuse the last one's.
  for (uint32_t samples : {16u, 9u, 16u, 25u}) {
    uint32_t n = samples == 9 ? 3 : samples == 16 ? 4 : 5;
    std::set<std::pair<int, int>> cells;
    for (uint32_t i = 0; i < samples; ++i)
      cells.insert(cell_of(sample_pixel(context(SamplerKind::jittered, i, samples)), int(n)));
    CAPTURE(samples);
    CHECK(cells.size() == samples);
  }
}

TEST_CASE("sampler: Sobol dimension 1 by shift-and-mask steps is the product with its generator matrix") {
  // The generator matrix from the direction numbers of the polynomial x + 1 (m_k = m_{k-1} ^ 2 m_{k-1}),
  // column k the bit-reversed direction number m_k 2^(31-k), as Joe and Kuo define them.
  uint32_t columns[32];
  uint32_t m = 1;
  for (int k = 0; k < 32; ++k) {
    columns[k] = sobol::reverse_bits(m << (31 - k));
    m ^= m << 1;
  }
  uint32_t state = 12345;
  for (int n = 0; n < 200000; ++n) {
    uint32_t index = n < 70000 ? uint32_t(n) : (state = state * 1664525u + 1013904223u);
    uint32_t product = 0;
    for (int k = 0; k < 32; ++k)
      if (index >> k & 1) product ^= columns[k];
    CAPTURE(index);
    REQUIRE(sobol::sobol1_reversed(index) == product);
  }
}

TEST_CASE("sampler: pairs drawn many at once are sample_2d's and sample_1d's to the bit, for every sampler") {
  SampleLanes lanes;
  for (SamplerKind kind : {SamplerKind::sobol, SamplerKind::jittered, SamplerKind::grid, SamplerKind::random}) {
    CAPTURE(int(kind));
    std::vector<SampleContext> contexts;
    std::vector<uint32_t> dimensions;
    uint32_t state = 99;
    auto next = [&] { return state = state * 1664525u + 1013904223u; };
    lanes.count = 0;
    for (int i = 0; i < SampleLanes::capacity; ++i) {
      // Small and huge indices, pixels and seeds, and dimension 0 (Sobol's unshuffled pixel pair).
      SampleContext c{kind, i % 3 ? next() % 4096 : next(), i % 5 ? next() % 256 : next(), 64,
                      i % 7 ? next() % 4 : next()};
      uint32_t d = i % 11 == 0 ? 0 : 2 + next() % 200;
      contexts.push_back(c);
      dimensions.push_back(d);
      lanes.add(c, d);
    }
    // Counts that end inside and at the end of a SIMD register, with every instruction set this
    // CPU runs (they must agree, or shards from different machines would not merge to one image).
    for (LaneIsa isa : {LaneIsa::best, LaneIsa::baseline, LaneIsa::avx2}) {
      if (!lane_isa_available(isa)) continue;
      CAPTURE(int(isa));
      for (int count : {SampleLanes::capacity, 13, 8, 1}) {
        lanes.count = count;
        std::fill(lanes.x, lanes.x + count, -1.0f);
        draw_sample_lanes(kind, lanes, isa);
        for (int i = 0; i < count; ++i) {
          CAPTURE(i);
          const SampleContext& c = contexts[size_t(i)];
          uint32_t d = dimensions[size_t(i)];
          vec2 expected = sample_2d(c, d);
          REQUIRE(std::bit_cast<uint32_t>(lanes.x[i]) == std::bit_cast<uint32_t>(expected.x));
          REQUIRE(std::bit_cast<uint32_t>(lanes.y[i]) == std::bit_cast<uint32_t>(expected.y));
          if (d > 0)
            REQUIRE(std::bit_cast<uint32_t>(lanes.x[i]) == std::bit_cast<uint32_t>(sample_1d(c, d)));
          else if (kind == SamplerKind::sobol || kind == SamplerKind::random)  // the others stratify it
            REQUIRE(std::bit_cast<uint32_t>(lanes.y[i]) == std::bit_cast<uint32_t>(sample_pixel(c).y));
        }
      }
    }
  }
}

TEST_CASE("sampler: grid and jittered pixel positions drawn many at once are sample_pixel's to the bit") {
  uint32_t state = 5;
  auto next = [&] { return state = state * 1664525u + 1013904223u; };
  std::vector<uint32_t> pixels;
  for (int i = 0; i < 150; ++i) pixels.push_back(i % 3 ? next() % 100000 : next());  // beyond one 64-lane chunk
  std::vector<float> x(pixels.size()), y(pixels.size());
  // Sample counts from one (the centre) through square, non-square and larger than any cell
  // count a permutation walks once; indices at and past the count (remainder by the cells).
  for (uint32_t samples : {1u, 2u, 7u, 16u, 81u, 100u, 1000u, 4099u})
    for (SamplerKind kind : {SamplerKind::grid, SamplerKind::jittered})
      for (uint32_t seed : {0u, 3u, 0xdeadbeefu})
        for (LaneIsa isa : {LaneIsa::best, LaneIsa::baseline, LaneIsa::avx2}) {
          if (!lane_isa_available(isa)) continue;
          for (uint32_t index : {0u, 1u, samples / 2, samples - 1, samples + 5}) {
            CAPTURE(samples);
            CAPTURE(int(kind));
            CAPTURE(seed);
            CAPTURE(int(isa));
            CAPTURE(index);
            for (int count : {int(pixels.size()), 64, 9, 1}) {
              draw_stratified_pixels(kind, samples, index, seed, pixels.data(), count, x.data(), y.data(), isa);
              for (int i = 0; i < count; ++i) {
                vec2 expected = sample_pixel({kind, pixels[size_t(i)], index, samples, seed});
                REQUIRE(std::bit_cast<uint32_t>(x[size_t(i)]) == std::bit_cast<uint32_t>(expected.x));
                REQUIRE(std::bit_cast<uint32_t>(y[size_t(i)]) == std::bit_cast<uint32_t>(expected.y));
              }
            }
          }
        }
}
