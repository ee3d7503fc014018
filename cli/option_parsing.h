// Parsing the command line's value syntaxes (X,Y,Z triples, mode and sampler names, windows).
#pragma once

#include <CLI/CLI.hpp>

#include <limits>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "log_level.h"
#include "memory/memory_budget.h"
#include "number_parsing.h"
#include "render/render_options.h"

namespace radiant::cli {

// Parses a command's arguments (argv[0] is the command) with what CLI11 does not check: a flag
// given twice (`--spp 4 --spp=8`) is an error naming both, and an unknown flag is an error that
// suggests the nearest known ones (`--sampels`: did you mean --sampler or --spp?). Throws
// CLI::ParseError.
void parse_arguments(CLI::App& app, int argc, char** argv);
// The same for the words of a script line (the first word is the command).
void parse_arguments(CLI::App& app, std::vector<std::string> words);

// Each throws CLI::ValidationError naming `flag` on bad input. Numbers must be finite as floats.
RenderMode parse_mode(const std::string& flag, const std::string& text);
SamplerKind parse_sampler(const std::string& flag, const std::string& text);
LightSampler parse_light_sampler(const std::string& flag, const std::string& text);
Projection parse_camera_type(const std::string& flag, const std::string& text);
TextureFilterMode parse_texture_filter(const std::string& flag, const std::string& text);
PathBatching parse_batching(const std::string& flag, const std::string& text);
// "2" (pixels) or "0.01m" (world units): a positive width.
LineWidth parse_line_width(const std::string& flag, const std::string& text);
PixelWindow parse_window(const std::string& flag, const std::string& text);
// "I/K" with 0 <= I < K <= 65536, and "A:B" sample indices.
ShardSpec parse_shard(const std::string& flag, const std::string& text);
ShardSplit parse_split(const std::string& flag, const std::string& text);
SampleRange parse_sample_range(const std::string& flag, const std::string& text);
std::vector<std::string> parse_aovs(const std::string& flag, const std::string& text);
// --progress auto|bar|lines|none as the style a command prints: auto is the bar when stderr is a
// terminal and lines when it is not (a log); none when `quiet`.
ProgressStyle parse_progress(const std::string& flag, const std::string& text, bool quiet);
// --time-limit's check: seconds in (0, max_time_limit_seconds] (CLI::PositiveNumber lets NaN
// through, and 1e308 seconds overflows the deadline).
CLI::Validator time_limit_range();

// GiB as bytes: finite, positive and at least one byte; beyond what 64 bits count means no cap.
uint64_t parse_memory_limit(const std::string& flag, const std::string& text);
// The budget of a command: --max-memory when given, else a quarter of RAM.
MemoryBudget command_memory_budget(const std::optional<uint64_t>& max_memory_bytes);
const char* mode_name(RenderMode mode);
const char* sampler_name(SamplerKind kind);

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
