// The flags `render`, `converge`, `batch` and `session` share: their table (names, help, checks)
// and their conversion into RenderOptions. The value syntaxes are in flag_values.h.
#pragma once

#include <CLI/CLI.hpp>

#include <limits>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "flag_values.h"
#include "log_level.h"
#include "memory/memory_budget.h"
#include "number_parsing.h"
#include "unknown_flags.h"
#include "render/render_options.h"

namespace radiant::cli {

// The budget of a command: --max-memory when given, else a quarter of RAM.
MemoryBudget command_memory_budget(const std::optional<uint64_t>& max_memory_bytes);

// The options shared by `render`, `converge` and `batch`, bound to `app`; call `finish` after
// parsing to convert the string flags.
struct RenderFlags {
  RenderOptions options;
  std::string mode, sampler, light_sampler, env_color, crop, aovs, look_from, look_at, up, view, camera_type, variant;
  std::string texture_filter, line_width;
  std::string env, background, orbit;
  float env_intensity = 1, env_rotation = 0;
  std::string batching;
  std::string shard, split, sample_range, filter;
  int width = 0, height = 0, spp = 0, max_depth = 0, indirect_paths = 0, gltf_scene = -1;
  float fov = 0;
  float ortho_height = 0;  // unset: 0
  float filter_width = 0;  // unset: 0
  float lens_radius = -1, focus_distance = 0;  // unset: -1, 0
  int blades = -1;                             // unset: -1
  bool allow_external_files = false;
  bool no_metadata = false;                 // --no-metadata (image flags only)
  bool transparent = false;
  std::string max_memory;                   // GiB, as given
  std::optional<uint64_t> max_memory_bytes;  // set by finish() when --max-memory is given
  LogLevelFlags log;                         // -q, -qq, --quiet, --log-level
  void bind(CLI::App& app, bool image_flags);
  void finish();
  // The command's memory budget: --max-memory, or a quarter of RAM.
  MemoryBudget memory_budget() const;
};

}  // namespace radiant::cli
