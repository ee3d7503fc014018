// Merging shards: the checks that they belong to one render and cover the image x [0, spp)
// exactly once, and the exact addition of their accumulators (docs/distributed.md).
#pragma once

#include <string>
#include <vector>

#include "film/film.h"
#include "film/shard_file.h"

namespace radiant {

struct NamedShard {
  std::string path;
  ShardInfo info;
};

// The info of the merged render (the full image, samples [0, spp) of the largest spp), or
// std::runtime_error with one line saying what is wrong: a mismatch naming both files, an
// interrupted shard, an overlap naming both files, or what is missing ("missing: 3,7" when the
// shards came from --shard I/K, else the first region and sample range no shard covers).
// `whole_image` false (merge --keep-accum, a step of a hierarchical merge) asks the shards to
// cover exactly their bounding region x sample range instead, which the info then describes.
ShardInfo check_shards(const std::vector<NamedShard>& shards, bool whole_image = true);

// Adds every sample of `shard` into `merged` (a film whose window holds the shard's, with AOV
// coverage and odd-half sums when both have them).
void add_shard(Film& merged, const Film& shard);

}  // namespace radiant
