#include "render/shard_plan.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "render/render_option_names.h"

namespace radiant {

namespace {

// [index * total / count, (index + 1) * total / count): consecutive, covering [0, total).
void cut(int64_t total, int index, int count, int64_t& begin, int64_t& end) {
  begin = total * index / count;
  end = total * (index + 1) / count;
}

// Columns of a grid of `count` tiles whose cells are as square as the image allows.
int tile_columns(int count, int width, int height) {
  int best = 1;
  double best_error = INFINITY;
  for (int columns = 1; columns <= count; ++columns) {
    if (count % columns) continue;
    double cell_aspect = (double(width) / columns) / (double(height) / (count / columns));
    double error = std::abs(std::log(cell_aspect));
    if (error < best_error) best = columns, best_error = error;
  }
  return best;
}

// Sample ranges of `both`: the largest divisor of `count` not above its square root.
int sample_pieces(int count) {
  int best = 1;
  for (int d = 1; d * d <= count; ++d)
    if (count % d == 0) best = d;
  return best;
}

PixelWindow tile_window(int tile, int tiles, int width, int height) {
  int columns = tile_columns(tiles, width, height), rows = tiles / columns;
  if (columns > width || rows > height)
    throw std::invalid_argument("--shard: a " + std::to_string(width) + "x" + std::to_string(height) +
                                " image cannot be cut into " + std::to_string(tiles) + " tiles of " +
                                std::to_string(columns) + " columns and " + std::to_string(rows) + " rows");
  int64_t x0, x1, y0, y1;
  cut(width, tile % columns, columns, x0, x1);
  cut(height, tile / columns, rows, y0, y1);
  return {int(x0), int(y0), int(x1), int(y1)};
}

SampleRange sample_range(int piece, int pieces, uint32_t spp) {
  if (uint32_t(pieces) > spp)
    throw std::invalid_argument("--shard: " + std::to_string(spp) + " samples per pixel cannot be cut into " +
                                std::to_string(pieces) + " sample ranges");
  int64_t begin, end;
  cut(spp, piece, pieces, begin, end);
  return {uint32_t(begin), uint32_t(end)};
}

}  // namespace

ShardPiece plan_shard(const ShardSpec& shard, int width, int height, uint32_t spp) {
  int samples = 1, tiles = 1;
  switch (shard.split) {
    case ShardSplit::tiles: tiles = shard.count; break;
    case ShardSplit::samples: samples = shard.count; break;
    case ShardSplit::both: samples = sample_pieces(shard.count), tiles = shard.count / samples; break;
  }
  return {tile_window(shard.index / samples, tiles, width, height), sample_range(shard.index % samples, samples, spp)};
}

const char* split_name(ShardSplit split) { return name_of(shard_split_names, split); }

}  // namespace radiant
