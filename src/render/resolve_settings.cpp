// Combining command-line options, the scene file's settings and the defaults.
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "render/camera.h"
#include "render/render.h"
#include "render/shard_plan.h"
#include "scene/scene_summary.h"
#include "sampling/pixel_filter.h"

namespace radiant {

namespace {

// A side as the message shows it: "80000", "5e+32".
std::string side_text(double side) {
  std::ostringstream text;
  text << side;
  return text.str();
}

void resolve_size(const RenderOptions& options, const SceneDesc& scene, ResolvedSettings& r) {
  // In double until checked: a side derived from an extreme aspect may not fit in an int.
  std::optional<double> width, height;
  double aspect = r.camera.aspect > 0 ? r.camera.aspect : 1.0;
  if (options.width.has_value() != options.height.has_value()) {
    // One side from the flags: the other keeps the shape the scene's image would have.
    const SceneSettings& own = scene.settings;
    if (own.width && own.height) aspect = double(*own.width) / double(*own.height);
    else if (r.camera.width > 0 && r.camera.height > 0) aspect = double(r.camera.width) / double(r.camera.height);
    if (options.width) width = *options.width;
    else height = *options.height;
  } else {
    if (std::optional<int> w = options.width ? options.width : scene.settings.width) width = *w;
    if (std::optional<int> h = options.height ? options.height : scene.settings.height) height = *h;
    if (!width && r.camera.width > 0) width = r.camera.width;
    if (!height && r.camera.height > 0) height = r.camera.height;
  }
  if (width && !height) height = std::max(1.0, std::round(*width / aspect));
  if (height && !width) width = std::max(1.0, std::round(*height * aspect));
  if (!width) {
    width = aspect >= 1 ? default_image_size : std::max(1.0, std::round(default_image_size * aspect));
    height = aspect >= 1 ? std::max(1.0, std::round(default_image_size / aspect)) : default_image_size;
  }
  if (!(*width >= 1 && *height >= 1 && *width <= 65536 && *height <= 65536))
    throw std::invalid_argument("image size " + side_text(*width) + "x" + side_text(*height) +
                                " is out of range (1 to 65536)");
  r.width = int(*width);
  r.height = int(*height);
}

// Camera rays start at the camera (across its lens, or across an orthographic view): they must lie within the
// range the accelerator can trace (scene/coordinate_range.h).
void check_camera_traceable(const ResolvedSettings& r, const PreparedScene& prepared) {
  double reach = max_component(abs(r.camera.position)) + r.camera.lens_radius;
  if (r.camera.projection == Projection::orthographic)
    reach += double(r.camera.ortho_height) * std::max(1.0, double(r.width) / r.height);
  if (!(reach <= 0.5 * prepared.accel->max_ray_coordinate))
    throw std::runtime_error(prepared.scene->source_path + ": the view reaches " + std::to_string(reach) +
                             " from the scene, beyond what its smallest instance scale lets radiant trace (" +
                             std::to_string(0.5 * prepared.accel->max_ray_coordinate) + ")");
}

// The pixels and samples this render takes: a shard's piece, or --crop and --sample-range.
void resolve_piece(const RenderOptions& options, ResolvedSettings& r) {
  r.window = {0, 0, r.width, r.height};
  r.samples = {0, uint32_t(r.spp)};
  if (options.shard) {
    ShardPiece piece = plan_shard(*options.shard, r.width, r.height, uint32_t(r.spp));
    r.window = piece.window, r.samples = piece.samples;
  }
  if (options.crop) {
    const PixelWindow& c = *options.crop;
    if (c.x0 < 0 || c.y0 < 0 || c.x1 > r.width || c.y1 > r.height || c.x0 >= c.x1 || c.y0 >= c.y1)
      throw std::invalid_argument("--crop must lie inside the " + std::to_string(r.width) + "x" +
                                  std::to_string(r.height) + " image with x0 < x1 and y0 < y1");
    r.window = c;
  }
  if (options.sample_range) {
    const SampleRange& range = *options.sample_range;
    if (range.begin >= range.end || range.end > uint32_t(r.spp))
      throw std::invalid_argument("--sample-range " + std::to_string(range.begin) + ":" + std::to_string(range.end) +
                                  " must be A:B with A < B <= the total spp (" + std::to_string(r.spp) + ")");
    r.samples = range;
  }
  bool split_samples = r.samples.begin != 0 || r.samples.end != uint32_t(r.spp);
  // A pixel's adaptive stop depends on all its earlier samples, which another shard takes.
  if (split_samples && options.noise_threshold > 0)
    throw std::invalid_argument("--noise-threshold cannot be split into sample ranges (tiles and --crop can)");
  // A time limit stops each shard at a different sample: the pieces would not add up to the image.
  if ((options.shard || options.sample_range) && options.time_limit_seconds > 0)
    throw std::invalid_argument("--time-limit cannot be used with --shard or --sample-range: shards must be complete");
}

// The environment: --env NAME or FILE and --env-color, else the scene's own, else the built-in
// studio for a scene that has no light of its own (docs/lights.md, "Default lighting").
void resolve_environment(const RenderOptions& options, const SceneDesc& scene, ResolvedSettings& r) {
  EnvironmentSpec& e = r.environment;
  e.color = scene.environment.color;
  e.map_path = scene.environment.map_path;
  e.map_scale = scene.environment.map_scale;
  if (!options.env_map.empty()) e.map_path = options.env_map, e.map_scale = 1;
  if (options.env_preset) {
    e = {};
    if (*options.env_preset == EnvironmentPreset::studio) e.studio = true;
    if (*options.env_preset == EnvironmentPreset::white) e.color = {1, 1, 1};
  }
  if (options.env_color) e.color = *options.env_color;
  bool chosen = options.env_preset || !options.env_map.empty() || options.env_color;
  if (!chosen && is_black(e.color) && e.map_path.empty() && !lights_itself(scene)) {
    e.studio = true;
    r.default_environment = true;
  }
  e.color = e.color * options.env_intensity;
  e.map_scale *= options.env_intensity;
  e.frame = make_environment_frame(r.world_up, options.env_rotation_degrees);
}

}  // namespace

int resolved_image_height(const RenderOptions& options, const SceneDesc& scene, const CameraDesc& camera) {
  ResolvedSettings r;
  r.camera = camera;
  resolve_size(options, scene, r);
  return r.height;
}

ResolvedSettings resolve_settings(const PreparedScene& prepared, const RenderOptions& options) {
  const SceneDesc& scene = *prepared.scene;
  ResolvedSettings r;
  if (options.world_up) r.world_up = normalize(*options.world_up);
  r.camera = world_view_camera(prepared, options, r.camera_framed);
  r.camera.position = to_render_space(r.camera.position, prepared.origin);
  for (CameraPose& pose : r.camera.motion) pose.position = to_render_space(pose.position, prepared.origin);
  resolve_size(options, scene, r);
  check_camera_traceable(r, prepared);

  resolve_environment(options, scene, r);
  RenderMode mode = options.mode ? *options.mode : scene.settings.mode.value_or(RenderMode::auto_select);
  if (mode == RenderMode::auto_select) mode = choose_auto_mode(scene, r.environment.exists(), r.mode_reason);
  r.mode = mode;
  bool whitted = mode == RenderMode::whitted;
  r.spp = options.spp ? *options.spp : scene.settings.spp.value_or(whitted ? default_whitted_spp : default_path_spp);
  r.max_depth = options.max_depth ? *options.max_depth
                                  : scene.settings.max_depth.value_or(whitted ? default_whitted_max_depth : default_path_max_depth);
  r.sampler = options.sampler ? *options.sampler
                              : scene.settings.sampler.value_or(whitted ? SamplerKind::jittered : SamplerKind::sobol);
  if (r.spp < 1) throw std::invalid_argument("--spp must be at least 1");
  if (r.max_depth < 1) throw std::invalid_argument("--max-depth must be at least 1");
  if (options.indirect_paths) {
    if (whitted) throw std::invalid_argument("--indirect-paths: only path tracing sends several paths on from a hit (--mode path or naive)");
    if (*options.indirect_paths < 1 || *options.indirect_paths > max_indirect_paths)
      throw std::invalid_argument("--indirect-paths must be in [1, " + std::to_string(max_indirect_paths) + "]");
    r.indirect_paths = *options.indirect_paths;
  }

  r.view = options.view ? *options.view : scene.settings.view.value_or(ViewTransform::standard);
  r.transparent = options.transparent ? *options.transparent : scene.settings.transparent.value_or(false);
  r.background = options.background.value_or(BackgroundKind::blur);
  r.background_color = options.background_color;
  if (r.background == BackgroundKind::transparent) r.transparent = true;
  r.filter = options.filter ? *options.filter : scene.settings.filter.value_or(PixelFilterKind::box);
  std::optional<float> width = options.filter_width ? options.filter_width : scene.settings.filter_width;
  r.filter_radius = width ? *width / 2 : default_filter_radius(r.filter);
  if (!(r.filter_radius > 0 && r.filter_radius <= max_filter_width / 2))
    throw std::invalid_argument("--filter-width must be in (0, " + std::to_string(int(max_filter_width)) + "] pixels");

  uint32_t needed = prepared.effects.mask;
  if (r.environment.exists()) needed |= effect_environment | effect_shadows | effect_indirect;
  else if (options.env_color || options.env_preset) needed &= ~effect_environment;
  r.effects = options.effects.empty() ? needed : apply_effects_override(needed, options.effects);
  r.compiled_variant = options.effects.find("all") != std::string::npos ? effect_all : smallest_variant(r.effects);

  resolve_piece(options, r);
  return r;
}

}  // namespace radiant
