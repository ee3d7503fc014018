// Turning a scheduler's task index into a piece of work: `--shard I/K` as a pixel window and a
// sample range. Every I in [0, K) together covers the image x [0, spp) exactly once.
#pragma once

#include <cstdint>

#include "render/render_options.h"

namespace radiant {

struct ShardPiece {
  PixelWindow window;
  SampleRange samples;
};

// The piece of `shard` in a `width` x `height` image of `spp` samples per pixel. Tiles form a
// grid of K cells as square as the image allows; `both` cuts into tiles x sample ranges with
// the sample ranges the smaller factor of K. Throws std::invalid_argument when the piece would
// be empty (more shards than rows, columns or samples to cut).
ShardPiece plan_shard(const ShardSpec& shard, int width, int height, uint32_t spp);

// "tiles", "samples", "both".
const char* split_name(ShardSplit split);

}  // namespace radiant
