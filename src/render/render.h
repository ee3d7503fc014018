// Rendering a loaded scene: settings resolution, the tile loop, statistics.
#pragma once

#include <memory>
#include <string>

#include "accel/scene_accel.h"
#include "film/film.h"
#include "image/image_writer.h"
#include "integrators/render_context.h"
#include "lights/light_table.h"
#include "materials/texture_pyramid.h"
#include "render/render_options.h"
#include "render/render_space.h"

namespace radiant {

// Derived state built once per scene and reused for every view (`radiant batch`).
struct PreparedScene {
  std::unique_ptr<SceneDesc> scene;  // in render space: world positions minus `origin`
  MemoryCharge scene_memory;         // the scene's own size, when its maker handed it over (frames)
  WorldPlacement world;              // the world positions, as loaded
  dvec3 origin = {0, 0, 0};
  std::unique_ptr<SceneAccel> accel;
  AccelLayout layout = AccelLayout::single_level;  // two-level for an animation's frames
  EffectSet effects;
  double build_seconds = 0;
  StrokeSizing stroke_sizing;  // how the accelerator sized lines and points, for this view
  MemoryBudget* budget = nullptr;  // what the accelerator is charged to (RenderOptions::memory)
  MemoryCharge accel_memory;       // the accelerator's estimated size, held against the budget
  // The textures' mip-maps (charged to `budget`), when the options prepared for are trilinear.
  std::unique_ptr<TexturePyramids> texture_pyramids;
};
// Takes a loaded (world-space) scene and builds it in the render space of the view `options`
// ask for. Charges options.memory (when given) for the accelerator before building it (rebuilds
// charge the same budget) and for the textures' mip-maps when options.texture_filter is
// trilinear; throws MemoryLimitError, and std::invalid_argument for a camera that does not
// exist or a bad view.
PreparedScene prepare_scene(SceneDesc scene, const RenderOptions& options = {},
                            AccelLayout layout = AccelLayout::single_level);
// Builds the accelerator of prepared.scene anew, charging its estimated size first.
void build_accel(PreparedScene& prepared);
// Moves `prepared` to the render origin the view of `options` needs, rebuilding the accelerator
// only when that origin differs from the current one; returns the seconds spent.
double prepare_view(PreparedScene& prepared, const RenderOptions& options);
// The camera of the view `options` ask for, in world space (`framed`: the scene has none).
CameraDesc world_view_camera(const PreparedScene& prepared, const RenderOptions& options, bool& framed);
// The same from a scene's world placement and settings, before it is prepared.
CameraDesc world_view_camera(const WorldPlacement& world, const SceneSettings& settings, const RenderOptions& options,
                             bool& framed);

// Settings after combining flags, the scene file's settings and the defaults.
struct ResolvedSettings {
  int width = 0, height = 0, spp = 1, max_depth = 1;
  int indirect_paths = 1;  // paths from each camera sample's first hit (path and naive modes)
  RenderMode mode = RenderMode::path;
  std::string mode_reason;  // why auto picked the mode ("" when given)
  SamplerKind sampler = SamplerKind::jittered;
  ViewTransform view = ViewTransform::standard;
  bool transparent = false;  // RGBA with coverage as alpha, the background not seen
  PixelFilterKind filter = PixelFilterKind::box;
  float filter_radius = 0.5f;  // pixels: half the filter's width
  LightSampler light_sampler = LightSampler::power;  // as the light table resolved `automatic`
  CameraDesc camera;
  bool camera_framed = false;  // no camera in the file: one frames the scene
  EnvironmentSpec environment;  // what lights the scene from afar
  // The environment was chosen because the scene has no light of its own.
  bool default_environment = false;
  vec3 world_up = {0, 1, 0};
  BackgroundKind background = BackgroundKind::blur;
  color3 background_color;
  uint32_t effects = 0;          // what runs: the scene's effects after --effects
  uint32_t compiled_variant = 0; // the compiled effect set that runs them
  PixelWindow window;
  SampleRange samples;  // the sample indices of each pixel this render takes, of [0, spp)
};

// Throws std::invalid_argument for settings that make no sense (names the flag). The camera is
// resolved in world space and placed in the prepared scene's render space.
ResolvedSettings resolve_settings(const PreparedScene& prepared, const RenderOptions& options);
// The image height a render of `scene` through `camera` with `options` takes (as resolve_settings).
int resolved_image_height(const RenderOptions& options, const SceneDesc& scene, const CameraDesc& camera);

// auto mode's rule (docs/effects.md): Whitted when it gives the path tracer's converged answer.
// `environment`: whether an environment lights the scene (its own, or one the flags give).
RenderMode choose_auto_mode(const SceneDesc& scene, bool environment, std::string& reason);

struct RenderStats {
  double build_seconds = 0, render_seconds = 0;
  RayCounts rays;
  uint64_t samples = 0;
  int passes = 0;
  // The samples per pixel every pixel reached (of its sample range), counting complete passes
  // only; a stopped render's pixels may hold up to one pass more.
  uint32_t samples_reached = 0;
  uint32_t min_pixel_samples = 0, max_pixel_samples = 0;
  uint32_t median_pixel_samples = 0, p90_pixel_samples = 0;  // the distribution adaptive sampling gives
  float estimated_relative_error = 0;  // mean over pixels of the relative standard error
  uint64_t untraceable_rays = 0;  // rays beyond the traceable range, taken as misses (none in a valid scene)
  bool stopped_by_time_limit = false;
  bool interrupted = false;  // stopped by RenderOptions::stop_request: the film is partial
};

struct RenderResult {
  ResolvedSettings settings;
  Film film;
  RenderStats stats;
  MemoryCharge image_memory;  // the film and the output image made from it, held until written
  std::vector<std::string> warnings;  // about the inputs read while rendering (the environment map)
};

// The threads a render works on: `requested` (--threads), at most the cores; all cores for 0.
int worker_threads(int requested);

// Throws MemoryLimitError when options.memory refuses the film, image or lights.
RenderResult render_prepared(const PreparedScene& prepared, const RenderOptions& options);

// What a render of `width` x `height` pixels with `channels` output channels allocates per
// image: the film (with AOV sums when `with_aovs`, coverage sums when `with_alpha`), the sample
// counts and activity masks, the output image and its 8-bit conversion for PNG.
uint64_t render_image_bytes(int width, int height, size_t channels, bool with_aovs, bool with_alpha,
                            bool with_halves = false);

// Whether `aovs` names `name`.
bool wants_aov(const std::vector<std::string>& aovs, const std::string& name);

// The channels film_to_image makes: R, G, B, A when `with_alpha`, then those of each AOV
// ("albedo.R", "N.X", "Z", "noisy.R", "even.R" ... "odd.B", ...).
std::vector<std::string> output_channel_names(const std::vector<std::string>& aovs, bool with_alpha);

// The film as an image with the requested AOV channels (a cropped render's film is the window).
// A film with coverage sums gives an A channel: R, G, B are then associated (premultiplied) by
// it already, the background having added nothing.
OutputImage film_to_image(const Film& film, const std::vector<std::string>& aovs);
// How the image is to be stored, as the options ask: exposure, the resolved view transform, bit
// depth and half floats (src/image/view_transform.h).
void set_output_encoding(OutputImage& image, const RenderOptions& options, const ResolvedSettings& settings);

}  // namespace radiant
