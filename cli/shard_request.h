// `render --skip-existing` before the scene is loaded: what a shard's command line and files say
// without loading them, so that re-running a finished array task exits at once
// (docs/distributed.md, "Re-running an array").
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "memory/memory_budget.h"

namespace radiant::cli {

// `path` absolute with symlinks resolved; as given when that fails (a hash of it then differs
// from a resolvable path's, which only costs a load).
std::string resolved_path(const std::string& path);

// 16 hex digits over the command line that decides a shard's content: every flag given, by its
// long name and parsed words (order, `--spp=8` or `--spp 8`, and aliases do not matter), the
// scene's absolute path with symlinks resolved (the loader finds the scene's own files from
// there), and --env's likewise. Flags that cannot change a shard's bytes are left out: -o,
// --threads, --max-memory, --quiet, --stats, --skip-existing and the look of image outputs
// (--exposure, --view, --bit-depth, --half, --format).
std::string shard_request_hash(const CLI::App& app, const std::string& scene_path);

// Whether `output` already holds, complete, the shard this command line makes, as far as can be
// known without loading: its request hash, radiant version and Embree ISA are this run's, the
// scene file and every other file its render read hash as they did then, and its size and
// checksum show it undamaged. False whenever that
// cannot be shown (no file, an older shard without a request hash, a file gone): the caller
// then loads the scene and checks the whole metadata.
bool shard_unchanged_before_load(const std::string& output, const std::string& scene_path, const std::string& request_hash,
                                 MemoryBudget* budget);

}  // namespace radiant::cli
