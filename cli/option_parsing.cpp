#include "option_parsing.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>

#include "environment_flags.h"
#include "number_parsing.h"
#include "image/view_transform.h"
#include "render/render.h"
#include "sampling/pixel_filter.h"
#include "lights/light_table.h"
#include "scene/coordinate_range.h"
#include "scene/enum_names.h"

namespace radiant::cli {

RenderMode parse_mode(const std::string& flag, const std::string& text) {
  if (text == "whitted") return RenderMode::whitted;
  if (text == "path") return RenderMode::path;
  if (text == "naive") return RenderMode::naive;
  if (text == "auto") return RenderMode::auto_select;
  throw CLI::ValidationError(flag, "unknown mode '" + text + "' (expected whitted, path, naive or auto)");
}

SamplerKind parse_sampler(const std::string& flag, const std::string& text) {
  if (text == "grid") return SamplerKind::grid;
  if (text == "random") return SamplerKind::random;
  if (text == "jittered") return SamplerKind::jittered;
  if (text == "sobol") return SamplerKind::sobol;
  throw CLI::ValidationError(flag, "unknown sampler '" + text + "' (expected grid, random, jittered or sobol)");
}

LightSampler parse_light_sampler(const std::string& flag, const std::string& text) {
  if (text == "auto") return LightSampler::automatic;
  if (text == "power") return LightSampler::power;
  if (text == "bvh") return LightSampler::bvh;
  throw CLI::ValidationError(flag, "unknown light sampler '" + text + "' (expected auto, power or bvh)");
}

Projection parse_camera_type(const std::string& flag, const std::string& text) {
  if (std::optional<Projection> projection = value_named(projection_names, text)) return *projection;
  throw CLI::ValidationError(flag, "unknown camera type '" + text + "' (expected " + names_text(projection_names) + ")");
}

TextureFilterMode parse_texture_filter(const std::string& flag, const std::string& text) {
  if (text == "point") return TextureFilterMode::point;
  if (text == "bilinear") return TextureFilterMode::bilinear;
  if (text == "trilinear") return TextureFilterMode::trilinear;
  throw CLI::ValidationError(flag, "unknown texture filter '" + text + "' (expected point, bilinear or trilinear)");
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
  if (text == "none") return PathBatching::none;
  if (text == "camera") return PathBatching::camera_rays;
  if (text == "all") return PathBatching::all_rays;
  throw CLI::ValidationError(flag, "unknown batching '" + text + "' (expected none, camera or all)");
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
  if (text == "tiles") return ShardSplit::tiles;
  if (text == "samples") return ShardSplit::samples;
  if (text == "both") return ShardSplit::both;
  throw CLI::ValidationError(flag, "unknown split '" + text + "' (expected tiles, samples or both)");
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
    if (name != "albedo" && name != "normal" && name != "depth" && name != "variance" && name != "spp" &&
        name != "noisy" && name != "halves")
      throw CLI::ValidationError(
          flag, "unknown AOV '" + name + "' (expected albedo, normal, depth, variance, spp, noisy or halves)");
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

const char* mode_name(RenderMode mode) {
  switch (mode) {
    case RenderMode::whitted: return "whitted";
    case RenderMode::path: return "path";
    case RenderMode::naive: return "naive";
    case RenderMode::auto_select: return "auto";
  }
  return "?";
}

const char* sampler_name(SamplerKind kind) {
  switch (kind) {
    case SamplerKind::grid: return "grid";
    case SamplerKind::random: return "random";
    case SamplerKind::jittered: return "jittered";
    case SamplerKind::sobol: return "sobol";
  }
  return "?";
}

namespace {

// Edit distance with transpositions (optimal string alignment): "sampels" is 1 from "samples".
size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// Names other renderers use for our flags: pbrt's and Cycles' words.
const std::vector<std::pair<std::string, std::string>> flag_synonyms = {
    {"samples", "spp"},       {"sample", "spp"},         {"spp-max", "spp"},      {"out", "output"},
    {"outfile", "output"},    {"integrator", "mode"},    {"maxdepth", "max-depth"}, {"depth", "max-depth"},
    {"resolution", "width"},  {"xres", "width"},         {"yres", "height"},      {"nthreads", "threads"},
    {"environment", "env"},   {"hdri", "env"},           {"world", "env"}};

std::string suggestions(const CLI::App& app, const std::string& unknown) {
  std::vector<std::string> found;
  auto add = [&](const std::string& name) {
    if (std::find(found.begin(), found.end(), name) == found.end()) found.push_back(name);
  };
  for (const CLI::Option* option : app.get_options()) {
    for (const std::string& name : option->get_lnames()) {
      size_t distance = edit_distance(unknown, name);
      if (distance <= std::max<size_t>(1, name.size() / 3) || (unknown.size() >= 3 && name.rfind(unknown, 0) == 0))
        add("--" + name);
    }
  }
  for (const auto& [synonym, name] : flag_synonyms)
    if (edit_distance(unknown, synonym) <= std::max<size_t>(1, synonym.size() / 3) && app.get_option_no_throw("--" + name))
      add("--" + name);
  std::string text;
  for (size_t i = 0; i < found.size(); ++i) text += (i == 0 ? "" : i + 1 == found.size() ? " or " : ", ") + found[i];
  return text;
}

// The flags among `words` (not their values): unknown ones and repeated ones are errors.
void check_flag_words(const CLI::App& app, const std::vector<std::string>& words) {
  std::vector<std::pair<const CLI::Option*, std::string>> seen;
  for (const std::string& word : words) {
    if (word == "--") break;  // what follows is positional
    bool flag = word.size() >= 2 && word[0] == '-' && (word[1] == '-' || (word.size() == 2 && std::isalpha(static_cast<unsigned char>(word[1]))));
    if (!flag) continue;  // a value ("-1,2,3", "-5", "-")
    std::string name = word.substr(0, word.find('='));
    const CLI::Option* option = app.get_option_no_throw(name);
    if (!option) {
      if (name == "-h" || name == "--help" || name == "--version") continue;
      std::string near = suggestions(app, name.substr(name[1] == '-' ? 2 : 1));
      throw CLI::ValidationError(name, "unknown flag" + (near.empty() ? std::string(" (--help lists them)") : "; did you mean " + near + "?"));
    }
    for (const auto& [earlier, as] : seen)
      if (earlier == option) throw CLI::ValidationError(name, "given twice (" + as + " and " + word + ")");
    seen.emplace_back(option, word);
  }
}

}  // namespace

void parse_arguments(CLI::App& app, int argc, char** argv) {
  check_flag_words(app, std::vector<std::string>(argv + 1, argv + argc));
  app.parse(argc, argv);
}

void parse_arguments(CLI::App& app, std::vector<std::string> words) {
  check_flag_words(app, std::vector<std::string>(words.begin() + 1, words.end()));
  std::reverse(words.begin(), words.end());
  words.pop_back();  // the command name
  app.parse(words);
}

ProgressStyle parse_progress(const std::string& flag, const std::string& text, bool quiet) {
  ProgressStyle style;
  if (text == "auto") style = isatty(STDERR_FILENO) ? ProgressStyle::bar : ProgressStyle::lines;
  else if (text == "bar") style = ProgressStyle::bar;
  else if (text == "lines") style = ProgressStyle::lines;
  else if (text == "none") style = ProgressStyle::none;
  else throw CLI::ValidationError(flag, "'" + text + "' is not auto, bar, lines or none");
  return quiet ? ProgressStyle::none : style;
}

void RenderFlags::bind(CLI::App& app, bool image_flags) {
  if (image_flags) {
    app.add_option("--width", width, "Image width in pixels (default: from the scene or camera)")->check(CLI::Range(1, 65536));
    app.add_option("--height", height, "Image height in pixels")->check(CLI::Range(1, 65536));
    app.add_option("--spp", spp, "Samples per pixel (the maximum with --noise-threshold)")->check(CLI::Range(1, 1 << 24));
    app.add_option("--exposure", options.exposure, "Exposure in stops for PNG, TIFF, JPEG... (EXR stays linear)")
        ->check(number_in(-64, 64));
    app.add_option("--view", view, "View transform of PNG, TIFF, JPEG...: standard (sRGB), linear, filmic, agx, neutral (Khronos PBR Neutral) or aces");
    app.add_option("--bit-depth", options.bit_depth, "8 or 16 bits per channel for PNG and TIFF")
        ->check(CLI::IsMember({8, 16}));
    app.add_flag("--half", options.half_float, "EXR with 16-bit half floats instead of 32-bit");
    app.add_flag("--no-metadata", no_metadata,
                 "Record nothing about the render in the image (version, command, times...): the same render "
                 "then writes the same bytes");
    app.add_flag("--denoise", options.denoise,
                 "Denoise the image (feature-guided regression on albedo, normal and depth) before it is written");
    app.add_flag("--transparent", transparent,
                 "RGBA with alpha = coverage of geometry; the background is not seen but still lights the scene "
                 "(EXR premultiplied, PNG/TIFF straight alpha)");
  }
  app.add_option("--mode", mode, "Integrator: whitted, path, naive or auto (default auto)");
  app.add_option("--max-depth", max_depth, "Surface interactions that gather light (1 = direct only)")->check(CLI::Range(1, 1000));
  app.add_option("--indirect-paths", indirect_paths,
                 "Paths each camera sample sends on from its first hit (path tracing; default 1): its direct light "
                 "is taken once, its bounce this many times")
      ->check(CLI::Range(1, max_indirect_paths));
  app.add_option("--clamp-direct", options.clamp_direct,
                 "Path tracing: the most a sample's light from its first hit may add, per channel (0 = off; "
                 "cuts fireflies, darkens bright light)")
      ->check(number_in(0, std::numeric_limits<float>::max()));
  app.add_option("--clamp-indirect", options.clamp_indirect,
                 "Path tracing: the most each bounce's light may add to a sample, per channel (0 = off; cuts "
                 "fireflies, darkens bright indirect light)")
      ->check(number_in(0, std::numeric_limits<float>::max()));
  app.add_option("--threads", options.threads, "Worker threads (default: all cores); never changes the image")->check(CLI::Range(0, 1024));
  app.add_option("--seed", options.seed, "Random seed");
  app.add_option("--sampler", sampler, "grid, random, jittered (Whitted default) or sobol (path default)");
  app.add_option("--filter", filter, "Pixel filter: box (default), triangle, gaussian, mitchell or blackman-harris");
  app.add_option("--filter-width", filter_width,
                 "The filter's full width in pixels (default: box 1, gaussian 3, triangle, mitchell, blackman-harris 4)")
      ->check(positive_number(max_filter_width));
  app.add_option("--light-sampler", light_sampler,
                 "How the path tracer chooses a light: power, bvh (by estimated contribution) or auto (bvh from " +
                     std::to_string(light_bvh_min_lights) + " lights with a position; default)");
  app.add_option("--camera", options.camera, "Camera name or index (default: the first)");
  app.add_option("--scene", gltf_scene, "glTF scene index (default: the file's default scene)")->check(CLI::NonNegativeNumber);
  app.add_option("--variant", variant, "glTF material variant by name (KHR_materials_variants)");
  app.add_option("--env-color", env_color, "Uniform environment radiance R,G,B (linear)");
  app.add_option("--env", env,
                 "Environment: studio (the default for files with no light of their own), white, none, or an "
                 "equirectangular map (.exr, .hdr)");
  app.add_option("--env-intensity", env_intensity, "Multiplies the environment's radiance (default 1)")
      ->check(number_in(0, 1e6));
  app.add_option("--env-rotation", env_rotation,
                 "Turns the environment about the up axis, in degrees, counterclockwise seen from above (at 0 "
                 "the map's centre faces +X, as in Blender and three.js)")
      ->check(number_in(-36000, 36000));
  app.add_option("--background", background,
                 "What the camera sees behind the scene: blur (the environment blurred; default), env, "
                 "transparent or color:R,G,B");
  app.add_option("--look-from", look_from, "Camera position X,Y,Z");
  app.add_option("--look-at", look_at, "Point the camera looks at X,Y,Z");
  app.add_option("--up", up,
                 "The scene's up: an axis (+Z for z-up files) or X,Y,Z; turns the framing camera and the "
                 "environment, and is the up of a camera placed by --look-from/--look-at");
  app.add_option("--orbit", orbit,
                 "AZIMUTH,ELEVATION[,DISTANCE]: the framing camera turned about the model in degrees, and "
                 "its distance as a multiple of the framing one");
  app.add_option("--fov", fov, "Vertical field of view in degrees (a fisheye's whole one, up to 360)")
      ->check(positive_number(360));
  app.add_option("--camera-type", camera_type,
                 "perspective, orthographic (framing the scene unless placed by the flags), equirect (360 degrees) or fisheye");
  app.add_option("--ortho-height", ortho_height, "An orthographic view's full height in scene units (default: the scene's)")
      ->check(positive_number(max_scene_coordinate));
  app.add_option("--lens-radius", lens_radius, "Thin-lens aperture radius in scene units (0 = pinhole)")
      ->check(number_in(0, max_scene_coordinate));
  app.add_option("--focus-distance", focus_distance, "Distance in focus along the view (default: to --look-at)")
      ->check(positive_number(max_scene_coordinate));
  app.add_option("--blades", blades, "Aperture blades: a polygonal bokeh (0 = round)")->check(CLI::Range(0, 64));
  app.add_option("--texture-filter", texture_filter,
                 "point (nearest texel), bilinear (full resolution) or trilinear (mip-mapped by the pixel's "
                 "footprint; default)");
  app.add_option("--line-width", line_width,
                 "Width of lines and points without one of their own: pixels at their distance (default 1), or "
                 "world units with a trailing m (0.01m)");
  app.add_option("--batching", batching,
                 "How paths share ray tracing: all (paths advance together, every ray in streams; default), "
                 "camera (a tile's camera rays as packets, then each path alone) or none; the image is the same");
  app.add_option("--effects", options.effects, "Switch effects off/on: e.g. -shadows,-indirect, or 'all' (generic integrator)");
  app.add_flag("--allow-external-files", allow_external_files, "Let scene files refer to files outside their folder");
  app.add_option("--max-memory", max_memory,
                 "Memory cap in GiB for loading and rendering: work that would need more is refused before it "
                 "allocates (default 1/4 of RAM)");
  log.bind(app);
}

void RenderFlags::finish() {
  if (width) options.width = width;
  if (height) options.height = height;
  if (spp) options.spp = spp;
  if (max_depth) options.max_depth = max_depth;
  if (indirect_paths) options.indirect_paths = indirect_paths;
  if (!mode.empty()) options.mode = parse_mode("--mode", mode);
  if (!sampler.empty()) options.sampler = parse_sampler("--sampler", sampler);
  if (!view.empty()) {
    try {
      options.view = parse_view_transform(view);
    } catch (const std::invalid_argument& e) {
      throw CLI::ValidationError("--view", e.what());
    }
  }
  if (transparent) options.transparent = true;
  if (!filter.empty()) {
    try {
      options.filter = parse_pixel_filter(filter);
    } catch (const std::invalid_argument& e) {
      throw CLI::ValidationError("--filter", e.what());
    }
  }
  if (filter_width > 0) options.filter_width = filter_width;
  if (!texture_filter.empty()) options.texture_filter = parse_texture_filter("--texture-filter", texture_filter);
  if (!batching.empty()) options.path_batching = parse_batching("--batching", batching);
  if (!line_width.empty()) options.line_width = parse_line_width("--line-width", line_width);
  if (!light_sampler.empty()) options.light_sampler = parse_light_sampler("--light-sampler", light_sampler);
  if (!env_color.empty()) {
    vec3 c = parse_vec3("--env-color", env_color);
    if (min_component(c) < 0) throw CLI::ValidationError("--env-color", "radiance cannot be negative");
    options.env_color = c;
  }
  if (!crop.empty()) options.crop = parse_window("--crop", crop);
  if (!shard.empty()) {
    if (!crop.empty() || !sample_range.empty())
      throw CLI::ValidationError("--shard", "takes its region and samples itself: not with --crop or --sample-range");
    options.shard = parse_shard("--shard", shard);
    if (!split.empty()) options.shard->split = parse_split("--split", split);
  } else if (!split.empty()) {
    throw CLI::ValidationError("--split", "needs --shard I/K");
  }
  if (!sample_range.empty()) options.sample_range = parse_sample_range("--sample-range", sample_range);
  if (!aovs.empty()) options.aovs = parse_aovs("--aov", aovs);
  if (wants_aov(options.aovs, "noisy") && !options.denoise)
    throw CLI::ValidationError("--aov", "noisy is the image before denoising: it needs --denoise");
  if (options.denoise && (!shard.empty() || !sample_range.empty()))
    throw CLI::ValidationError("--denoise", "is a step after merge: not with --shard or --sample-range");
  if (!look_from.empty()) options.camera_override.look_from = parse_vec3("--look-from", look_from);
  if (!look_at.empty()) options.camera_override.look_at = parse_vec3("--look-at", look_at);
  if (!up.empty()) {
    options.world_up = parse_up("--up", up);
    // A file's camera keeps its own roll; a camera placed by the flags stands on this up.
    if (!look_from.empty() || !look_at.empty()) options.camera_override.up = options.world_up;
  }
  if (!orbit.empty()) options.orbit = parse_orbit("--orbit", orbit);
  if (!env.empty()) parse_environment_choice(env, options);
  options.env_intensity = env_intensity;
  options.env_rotation_degrees = env_rotation;
  if (!background.empty()) {
    parse_background(background, options);
    if (transparent && options.background != BackgroundKind::transparent)
      throw CLI::ValidationError("--background", "contradicts --transparent");
  }
  if (fov != 0) options.camera_override.fov_degrees = fov;
  if (ortho_height > 0) options.camera_override.ortho_height = ortho_height;
  if (!camera_type.empty()) options.camera_override.projection = parse_camera_type("--camera-type", camera_type);
  if (lens_radius >= 0) options.camera_override.lens_radius = lens_radius;
  if (focus_distance > 0) options.camera_override.focus_distance = focus_distance;
  if (blades == 1 || blades == 2) throw CLI::ValidationError("--blades", "an aperture needs 0 (round) or at least 3 blades");
  if (blades >= 0) options.camera_override.aperture_blades = blades;
  if (!max_memory.empty()) max_memory_bytes = parse_memory_limit("--max-memory", max_memory);
  LogLevel level = log.level();
  options.quiet = !shows(level, LogLevel::info);
  options.quiet_warnings = !shows(level, LogLevel::warning);
}

MemoryBudget command_memory_budget(const std::optional<uint64_t>& max_memory_bytes) {
  if (max_memory_bytes) return MemoryBudget(*max_memory_bytes, "--max-memory");
  return MemoryBudget(default_memory_limit(), default_memory_limit_source);
}

MemoryBudget RenderFlags::memory_budget() const { return command_memory_budget(max_memory_bytes); }

}  // namespace radiant::cli
