// Fingerprints that say whether shards belong to one render: a hash of the scene's files and a
// hash of every resolved setting that changes a pixel (docs/distributed.md).
#pragma once

#include <string>
#include <vector>

#include "render/render.h"

namespace radiant {

// FNV-1a over the bytes of every file, in order, with each path's length and name left out (a
// copied scene folder hashes the same); 16 hex digits. Throws std::runtime_error naming a file
// that cannot be read.
std::string files_hash(const std::vector<std::string>& paths);

// FNV-1a over `text`'s bytes; 16 hex digits.
std::string text_hash(const std::string& text);

// 16 hex digits over the settings a shard's pixels depend on, exactly (floats by their bits):
// size, mode, depth, sampler, seed, camera, environment, effects, the AOV sums kept, and the
// total spp when the sampler's strata depend on it (grid, jittered). Not the window or the sample
// range, which differ between shards of one render.
std::string settings_hash(const ResolvedSettings& settings, const RenderOptions& options);

}  // namespace radiant
