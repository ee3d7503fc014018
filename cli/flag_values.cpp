#include "flag_values.h"

#include <unistd.h>

#include <cmath>
#include <limits>

#include "number_parsing.h"
#include "render/output_image.h"
#include "render/render_option_names.h"
#include "scene/coordinate_range.h"

namespace radiant::cli {

namespace {

// The value `table` names `text`, or an error naming the flag and the choices.
template <class Enum, size_t N>
Enum parse_named(const std::string& flag, const std::string& text, const std::pair<Enum, const char*> (&table)[N],
                 const std::string& what) {
  if (std::optional<Enum> value = value_named(table, text)) return *value;
  throw CLI::ValidationError(flag, "unknown " + what + " '" + text + "' (expected " + names_text(table) + ")");
}

}  // namespace

RenderMode parse_mode(const std::string& flag, const std::string& text) {
  return parse_named(flag, text, render_mode_names, "mode");
}

SamplerKind parse_sampler(const std::string& flag, const std::string& text) {
  return parse_named(flag, text, sampler_names, "sampler");
}

LightSampler parse_light_sampler(const std::string& flag, const std::string& text) {
  return parse_named(flag, text, light_sampler_names, "light sampler");
}

Projection parse_camera_type(const std::string& flag, const std::string& text) {
  return parse_named(flag, text, projection_names, "camera type");
}

TextureFilterMode parse_texture_filter(const std::string& flag, const std::string& text) {
  return parse_named(flag, text, texture_filter_names, "texture filter");
}

LineWidth parse_line_width(const std::string& flag, const std::string& text) {
  LineWidth width;
  width.in_pixels = text.empty() || text.back() != 'm';
  width.value = float(parse_number(flag, width.in_pixels ? text : text.substr(0, text.size() - 1)));
  if (!(width.value > 0) || width.value > max_scene_coordinate)
    throw CLI::ValidationError(flag, "'" + text + "' must be a positive width (pixels, or world units with 'm')");
  return width;
}

PathBatching parse_batching(const std::string& flag, const std::string& text) {
  return parse_named(flag, text, path_batching_names, "batching");
}

PixelWindow parse_window(const std::string& flag, const std::string& text) {
  auto parts = split(text, ',');
  if (parts.size() != 4) throw CLI::ValidationError(flag, "expected X0,Y0,X1,Y1 in pixels, got '" + text + "'");
  int v[4];
  for (int i = 0; i < 4; ++i) {
    double d = parse_number(flag, parts[i]);
    if (d != std::floor(d) || d < 0 || d > 1e6) throw CLI::ValidationError(flag, "'" + parts[i] + "' is not a pixel index");
    v[i] = int(d);
  }
  return {v[0], v[1], v[2], v[3]};
}

namespace {

// A whole number in [low, high] written as one.
int64_t parse_index(const std::string& flag, const std::string& text, int64_t low, int64_t high, const char* what) {
  double d = 0;
  size_t used = 0;
  if (!read_float_number(text, d, used) || d != std::floor(d) || d < double(low) || d > double(high) ||
      text.find_first_not_of("0123456789") != std::string::npos)
    throw CLI::ValidationError(flag, "'" + text + "' is not " + what);
  return int64_t(d);
}

}  // namespace

ShardSpec parse_shard(const std::string& flag, const std::string& text) {
  auto parts = split(text, '/');
  if (parts.size() != 2) throw CLI::ValidationError(flag, "expected I/K (shard I of K, from 0), got '" + text + "'");
  ShardSpec shard;
  shard.count = int(parse_index(flag, parts[1], 1, 65536, "a shard count from 1 to 65536"));
  shard.index = int(parse_index(flag, parts[0], 0, shard.count - 1, "a shard index from 0 to K-1"));
  return shard;
}

ShardSplit parse_split(const std::string& flag, const std::string& text) {
  return parse_named(flag, text, shard_split_names, "split");
}

SampleRange parse_sample_range(const std::string& flag, const std::string& text) {
  auto parts = split(text, ':');
  if (parts.size() != 2) throw CLI::ValidationError(flag, "expected A:B (samples A to B-1 of each pixel), got '" + text + "'");
  SampleRange range;
  range.begin = uint32_t(parse_index(flag, parts[0], 0, 1 << 24, "a sample index"));
  range.end = uint32_t(parse_index(flag, parts[1], 0, 1 << 24, "a sample index"));
  if (range.begin >= range.end) throw CLI::ValidationError(flag, "'" + text + "' is empty: A must be less than B");
  return range;
}

std::vector<std::string> parse_aovs(const std::string& flag, const std::string& text) {
  std::vector<std::string> aovs;
  for (const std::string& name : split(text, ',')) {
    if (name.empty()) continue;
    if (!find_aov(name)) {
      std::vector<std::string> known;
      for (const AovLayout& aov : aov_layouts) known.push_back(aov.name);
      throw CLI::ValidationError(flag, "unknown AOV '" + name + "' (expected " + choices_text(known) + ")");
    }
    aovs.push_back(name);
  }
  return aovs;
}

CLI::Validator time_limit_range() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double seconds = 0;
        if (CLI::detail::lexical_cast(text, seconds) && seconds > 0 && seconds <= max_time_limit_seconds) return "";
        return "'" + text + "' is not a number of seconds in (0, 1e9]";
      },
      "SECONDS");
}

uint64_t parse_memory_limit(const std::string& flag, const std::string& text) {
  double gib = parse_number(flag, text);
  if (!(gib > 0)) throw CLI::ValidationError(flag, "'" + text + "' is not a positive number of GiB");
  double bytes = gib * double(uint64_t(1) << 30);
  if (bytes < 1) throw CLI::ValidationError(flag, text + " GiB is less than one byte");
  if (bytes >= 18446744073709551616.0) return std::numeric_limits<uint64_t>::max();  // 2^64: no cap
  return uint64_t(bytes);
}

const char* mode_name(RenderMode mode) { return name_of(render_mode_names, mode); }

const char* sampler_name(SamplerKind kind) { return name_of(sampler_names, kind); }

ProgressStyle parse_progress(const std::string& flag, const std::string& text, bool quiet) {
  ProgressStyle style;
  if (text == "auto") style = isatty(STDERR_FILENO) ? ProgressStyle::bar : ProgressStyle::lines;
  else if (text == "bar") style = ProgressStyle::bar;
  else if (text == "lines") style = ProgressStyle::lines;
  else if (text == "none") style = ProgressStyle::none;
  else throw CLI::ValidationError(flag, "'" + text + "' is not auto, bar, lines or none");
  return quiet ? ProgressStyle::none : style;
}

}  // namespace radiant::cli
