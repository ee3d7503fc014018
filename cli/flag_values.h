// The command line's value syntaxes: enum names, windows, shards, sample ranges, AOV lists,
// memory sizes. Numbers and X,Y,Z triples are in number_parsing.h.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "render/render_options.h"

namespace radiant::cli {

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
// The words --mode and --sampler take for each value (scene/enum_names.h).
const char* mode_name(RenderMode mode);
const char* sampler_name(SamplerKind kind);

}  // namespace radiant::cli
