// --shard I/K as pixel windows and sample ranges: every K covers the image x [0, spp) once.
#include <doctest/doctest.h>

#include <stdexcept>
#include <vector>

#include "render/shard_plan.h"

using namespace radiant;

namespace {

// How many shards of K hold each (pixel, sample) of a width x height x spp render.
std::vector<int> coverage(int count, ShardSplit split, int width, int height, uint32_t spp) {
  std::vector<int> covered(size_t(width) * height * spp, 0);
  for (int index = 0; index < count; ++index) {
    ShardPiece piece = plan_shard({index, count, split}, width, height, spp);
    REQUIRE(piece.window.x0 < piece.window.x1);
    REQUIRE(piece.window.y0 < piece.window.y1);
    REQUIRE(piece.samples.begin < piece.samples.end);
    for (int y = piece.window.y0; y < piece.window.y1; ++y)
      for (int x = piece.window.x0; x < piece.window.x1; ++x)
        for (uint32_t s = piece.samples.begin; s < piece.samples.end; ++s) covered[(size_t(y) * width + x) * spp + s]++;
  }
  return covered;
}

}  // namespace

TEST_CASE("shard plan: every I/K for K up to 64 covers each pixel and sample exactly once, for every split") {
  for (ShardSplit split : {ShardSplit::tiles, ShardSplit::samples, ShardSplit::both})
    for (int count = 1; count <= 64; ++count) {
      CAPTURE(count);
      CAPTURE(split_name(split));
      std::vector<int> covered = coverage(count, split, 67, 23, 64);
      for (int c : covered) REQUIRE(c == 1);
    }
}

TEST_CASE("shard plan: tiles are as square as the image allows and samples are consecutive ranges") {
  ShardPiece tile = plan_shard({5, 8, ShardSplit::tiles}, 400, 200, 16);  // 4 columns x 2 rows of 100x100
  CHECK(tile.window == PixelWindow{100, 100, 200, 200});
  CHECK(tile.samples == SampleRange{0, 16});
  ShardPiece range = plan_shard({2, 4, ShardSplit::samples}, 400, 200, 256);
  CHECK(range.window == PixelWindow{0, 0, 400, 200});
  CHECK(range.samples == SampleRange{128, 192});
  // both: 4 = 2 tiles x 2 sample ranges; shard 3 is the second tile's second range.
  ShardPiece both = plan_shard({3, 4, ShardSplit::both}, 400, 200, 256);
  CHECK(both.window == PixelWindow{200, 0, 400, 200});
  CHECK(both.samples == SampleRange{128, 256});
}

TEST_CASE("shard plan: more shards than rows, columns or samples to cut is refused") {
  CHECK_THROWS_AS(plan_shard({0, 5, ShardSplit::tiles}, 4, 1, 8), std::invalid_argument);
  CHECK_THROWS_AS(plan_shard({0, 9, ShardSplit::samples}, 4, 4, 8), std::invalid_argument);
  CHECK_NOTHROW(plan_shard({7, 8, ShardSplit::samples}, 4, 4, 8));
}
