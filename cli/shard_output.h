// What `render --shard`/`--sample-range` write instead of an image: a shard file
// (film/shard_file.h) whose metadata `radiant merge` and `--skip-existing` check.
#pragma once

#include <string>

#include "film/shard_file.h"
#include "render/render.h"

namespace radiant::cli {

// Whether the render writes a shard: --shard or --sample-range was given.
bool writes_shard(const RenderOptions& options);

// The metadata of the shard that rendering `settings` of `prepared` makes, from the command line
// of `request_hash` (shard_request.h). Hashes the scene's files (throws std::runtime_error naming
// one that cannot be read).
ShardInfo make_shard_info(const PreparedScene& prepared, const ResolvedSettings& settings, const RenderOptions& options,
                          const std::string& request_hash);

// Whether `path` already holds exactly this shard, complete (--skip-existing after loading). A
// missing, unreadable, partial, damaged (its size or checksum wrong) or different file is not: the
// shard is rendered again. The request hash is not compared: a command line spelled differently
// may make the same shard.
bool shard_already_rendered(const std::string& path, const ShardInfo& expected, MemoryBudget* budget);

// "radiant: OUTPUT already holds this shard, complete; skipped" on stderr, unless quiet.
void report_shard_skipped(const std::string& output, bool quiet);

}  // namespace radiant::cli
