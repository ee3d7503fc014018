// A shard file: an EXR holding a film's exact accumulators (not its resolved pixels), placed in
// the full image by its data and display windows, with the metadata `radiant merge` checks.
// Channels: R, G, B (the mean, as float, for viewers), `samples` and `negative_samples` (uint32,
// src/film/film.h) and, for every exact sum (sum.R, sum2.R, ..., the coverage alpha.A of a
// transparent render and the AOV sums albedo.R, normal.X, depth.Z when kept), five uint32
// channels: its top bin (.t) and its high and low bins as two 32-bit halves each (.h0 .h1 .l0 .l1).
// A render with --aov halves adds the odd-indexed samples' sums (odd.R, odd.G, odd.B, five words
// each) and their counts (odd.samples, odd.negative_samples, uint32).
#pragma once

#include <string>
#include <vector>

#include "film/film.h"
#include "image/image_io_module.h"
#include "image/view_transform.h"
#include "memory/memory_budget.h"
#include "output/temporary_file.h"

namespace radiant {

// What a shard says about itself; equal fields of shards that belong together.
struct ShardInfo {
  std::string version;        // radiant's
  std::string scene_hash;     // files_hash of the scene's files
  std::string settings_hash;  // settings_hash of the render
  std::string isa;            // embree_kernels_name: the ISA and the Embree version
  std::string sampler;        // sampler_name
  uint32_t seed = 0;
  uint32_t spp = 0;                       // the render's total samples per pixel
  uint32_t sample_begin = 0, sample_end = 0;  // the samples of each pixel it holds
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;     // its region of the full image, half-open
  int full_width = 0, full_height = 0;
  std::vector<std::string> aovs;  // the AOVs of the render's output (merge writes them)
  bool transparent = false;       // holds coverage sums; merge writes RGBA
  // How the render's image is encoded (--exposure, --view or the scene's `view`, --bit-depth,
  // --half): no pixel of the shard depends on them, but merge writes its image with them, so
  // that it equals the one render's.
  DisplaySettings display;
  int bit_depth = 8;
  bool half = false;
  int shard_index = 0, shard_count = 0;  // I and K of --shard I/K; K = 0 for --crop/--sample-range
  std::string split;                     // tiles, samples or both with --shard
  std::string partial;            // why the render stopped early ("" when complete)
  // What --skip-existing checks before loading the scene (cli/shard_request.h): a hash of the
  // command line that made the shard, and the files the render read after the scene file itself
  // (absolute, symlinks resolved), whose bytes with the scene file's make scene_hash.
  std::string request_hash;
  std::vector<std::string> inputs;
  bool operator==(const ShardInfo&) const = default;
};

// The file's text attributes for `info`, and back. parse_shard_metadata throws
// std::runtime_error naming the attribute that is missing or malformed.
ImageMetadata shard_metadata(const ShardInfo& info);
ShardInfo parse_shard_metadata(const ImageMetadata& metadata);

// Writes `film` (its window, coverage and AOV sums as made) with `info`'s metadata and the
// attributes of `record` it does not hold already (image/render_metadata.h: how the render was
// made), charging `budget` for the channels first. Throws like write_image_file, and
// MemoryLimitError.
void write_shard(TemporaryFile& file, const Film& film, const ShardInfo& info, const ImageMetadata& record,
                 MemoryBudget* budget);

// The radiant:checksum a shard records: FNV-1a (16 hex digits) over its radiant attributes other
// than the checksum, by name, then a space and FNV-1a over its accumulator words (every channel
// but R, G, B), pixel by pixel, each pixel's channels by name. `words` holds `pixels` pixels of
// `channel_names.size()` words each, in that channel order.
std::string shard_checksum(const ImageMetadata& metadata, const std::vector<std::string>& channel_names,
                           const uint32_t* words, size_t pixels);

// The metadata of the shard at `path`, checked against its windows, its checksum (the metadata
// half) and the file's size (its last EXR chunk ends where the file does). Throws
// std::runtime_error "path: why" for a file that is not a shard radiant can merge.
ShardInfo read_shard_info(const std::string& path, MemoryBudget* budget);

// A shard's film and its charge against the budget, held as long as the film.
struct LoadedShard {
  Film film;
  MemoryCharge memory;
};

// The film of the shard at `path` (with AOV sums when its info lists AOVs, the odd half when they
// include halves, coverage sums when it is transparent), charging `budget` for it and for the read buffer first, its accumulators
// verified against its checksum. Throws std::runtime_error "path: why" (a pixel names itself) and
// MemoryLimitError.
LoadedShard read_shard_film(const std::string& path, const ShardInfo& info, MemoryBudget* budget);

}  // namespace radiant
