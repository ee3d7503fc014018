// The single options struct that carries every knob from the command line to the core.
// Unset optionals fall back to the scene file's settings, then to the defaults of the mode.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "accel/stroke_geometry.h"
#include "math/vec.h"
#include "memory/memory_budget.h"
#include "scene/scene_desc.h"

namespace radiant {

struct Film;

struct CameraOverride {
  std::optional<vec3> look_from, look_at, up;
  std::optional<float> fov_degrees;
  std::optional<Projection> projection;  // --camera-type
  std::optional<float> ortho_height;     // --ortho-height: an orthographic view's full height
  std::optional<float> lens_radius, focus_distance;
  std::optional<int> aperture_blades;
};

struct PixelWindow {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // half-open [x0, x1) x [y0, y1)
  bool operator==(const PixelWindow&) const = default;
};

// Sample indices [begin, end) of every pixel, out of the render's total spp.
struct SampleRange {
  uint32_t begin = 0, end = 0;
  bool operator==(const SampleRange&) const = default;
};

// How `--shard I/K` cuts the work: the image into K regions, [0, spp) into K ranges, or both.
enum class ShardSplit { tiles, samples, both };

// Shard `index` of `count` (0 <= index < count), resolved into a window and a sample range once
// the image size and spp are known (render/shard_plan.h).
struct ShardSpec {
  int index = 0, count = 1;
  ShardSplit split = ShardSplit::tiles;
};

// How a render's paths share their ray tracing (docs/performance.md measures each).
enum class PathBatching {
  none,         // each path alone, one ray at a time: the reference the tests compare with
  camera_rays,  // a tile's camera rays traced together as Embree packets, then each path alone
  // a tile's paths advance a vertex at a time together, their bounces and shadow rays traced
  // as Embree streams and their random numbers drawn and warped in SIMD (Integrator::batch):
  // the default, the fastest on the benchmark's Cornell boxes (docs/performance.md)
  all_rays,
};

// How a render reports its progress on stderr.
enum class ProgressStyle {
  none,
  bar,    // one line redrawn in place, erased at the end (a terminal)
  lines,  // a line at least every 10% or 30 s, with the samples reached, elapsed time and ETA (logs)
};

// --env NAME: a built-in environment (docs/lights.md, "Default lighting"); a file goes to env_map.
enum class EnvironmentPreset { studio, white, none };

// --background: what camera rays that leave the scene see. `blur` is the environment through a
// small blurred copy of its map (the environment itself when it has no map).
enum class BackgroundKind { blur, environment, color, transparent };

// --orbit: the framing camera turned about the scene's centre, relative to the framing view.
struct Orbit {
  float azimuth_degrees = 0;    // counterclockwise about the up axis, seen from above
  float elevation_degrees = 0;  // added to the framing view's elevation
  float distance = 1;           // a multiple of the distance that frames the scene
};

struct RenderOptions {
  std::optional<int> width, height, spp, max_depth;
  std::optional<int> indirect_paths;  // --indirect-paths
  std::optional<RenderMode> mode;
  std::optional<SamplerKind> sampler;
  LightSampler light_sampler = LightSampler::automatic;  // path and naive modes' light choice
  int threads = 0;  // 0 = all cores; more than the cores runs on the cores
  uint32_t seed = 0;
  std::string camera;  // name or index; empty = the first
  CameraOverride camera_override;
  std::optional<color3> env_color;
  std::string env_map;
  std::optional<EnvironmentPreset> env_preset;
  float env_intensity = 1;         // --env-intensity: scales the whole environment
  float env_rotation_degrees = 0;  // --env-rotation: about the up axis (lights/environment_map.h)
  // --up as the world's up: the framing camera's and the environment's (camera_override.up
  // holds it too, for a camera placed by the flags).
  std::optional<vec3> world_up;
  std::optional<Orbit> orbit;
  std::optional<BackgroundKind> background;
  color3 background_color;  // for BackgroundKind::color
  std::optional<PixelWindow> crop;
  std::optional<SampleRange> sample_range;  // --sample-range: only these samples of each pixel
  std::optional<ShardSpec> shard;           // --shard: sets the window and sample range
  std::string effects;          // --effects list, applied to the scene's effect set
  std::vector<std::string> aovs;  // albedo, normal, depth, variance, spp, noisy, halves
  // --denoise: the film also keeps the albedo, normal and depth sums and the odd samples' half,
  // which the denoiser (src/denoise/) reads.
  bool denoise = false;
  double time_limit_seconds = 0;  // 0 = none; at most max_time_limit_seconds
  // When set, the time limit ends here (the CLI starts it before loading the scene).
  std::optional<std::chrono::steady_clock::time_point> deadline;
  // When set and nonzero, the render stops at the next pixel, or the next sample of a tile traced in
  // packets (the CLI's SIGINT/SIGTERM handler).
  const std::atomic<int>* stop_request = nullptr;
  // A stop (the time limit or stop_request) waits for the first pass, one sample per pixel, so the
  // image it leaves has no empty pixel. A session's replaced render, discarded anyway, need not.
  bool stop_completes_first_pass = true;
  // Progressive rendering (`radiant session`): this is called after each complete pass with the
  // film and the samples per pixel it holds. Passes grow from one sample per pixel (1, 2, 4, ...)
  // whenever a render may stop early: with this, a time limit, a stop_request or a noise
  // threshold (render/pass_schedule.h). Each pixel still adds its samples in index order, so the
  // final film is the one-pass render's, bit for bit.
  std::function<void(const Film& film, uint32_t samples)> on_pass;
  // How the image is stored (src/image/view_transform.h): exposure in stops and the view
  // transform of 8- and 16-bit outputs (the scene's `view` setting, else standard), their bit
  // depth, and half floats for EXR.
  float exposure = 0;
  std::optional<ViewTransform> view;
  int bit_depth = 8;
  bool half_float = false;
  // --transparent: RGBA output whose alpha is the coverage of geometry; camera rays that miss
  // see no background (the environment still lights the scene), as Cycles' transparent film.
  std::optional<bool> transparent;
  // --filter and --filter-width: the pixel filter and its full width in pixels (twice pbrt's
  // radius); unset: the scene's, then box, and each filter's own default width.
  std::optional<PixelFilterKind> filter;
  std::optional<float> filter_width;
  // --texture-filter: how texture lookups filter (trilinear: mip-mapped by the pixel's footprint).
  TextureFilterMode texture_filter = TextureFilterMode::trilinear;
  // --line-width: lines and points without a width of their own, in pixels at their distance
  // from the camera (the view the scene is prepared for) or in world units.
  LineWidth line_width;
  float noise_threshold = 0;      // 0 = off
  // --min-spp: the samples every pixel takes before adaptive sampling may stop it; 0 derives
  // them from the threshold as Cycles does (render/pass_schedule.h).
  uint32_t min_spp = 0;
  // --clamp-direct, --clamp-indirect: the largest component a path's light from its first hit,
  // and from each later bounce, may add to a sample, as Cycles' sample clamps (0 = off). Fewer
  // fireflies, at the price of energy: a clamped render is darker where light is concentrated.
  float clamp_direct = 0, clamp_indirect = 0;
  float contribution_cutoff = 0.001f;  // Whitted: stop recursing below this weight
  // How paths share their ray tracing; every way gives the same image, bit for bit. The batch
  // (all_rays) is the fastest since its random numbers and warps run in SIMD.
  PathBatching path_batching = PathBatching::all_rays;
  bool quiet = false;          // no informational lines or progress on stderr (-q)
  bool quiet_warnings = false; // no warnings either, only errors (-qq, --quiet)
  // Progress on stderr (render/progress_meter.h): none, a line redrawn in place on a terminal, or
  // whole lines for logs. The CLI's --progress auto picks the bar on a terminal, lines off it.
  ProgressStyle progress = ProgressStyle::none;
  // --max-memory: charged for the film, the output image, the light table and the environment
  // map before they are allocated (the command's budget, shared with loading); null = no cap.
  MemoryBudget* memory = nullptr;
};

// About 31 years: a longer limit cannot be told from none, and its deadline would overflow the
// clock's 64-bit nanoseconds.
constexpr double max_time_limit_seconds = 1e9;

// Default samples per pixel and depth of each mode.
constexpr int default_whitted_spp = 4;
constexpr int default_path_spp = 64;
constexpr int default_whitted_max_depth = 10;
// The most paths a camera sample's first hit may send on (--indirect-paths): a batch holds all
// of one camera sample's (integrators/render_context.h, max_batch_paths).
constexpr int max_indirect_paths = 64;
constexpr int default_path_max_depth = 8;
constexpr int default_image_size = 512;

}  // namespace radiant
