#include "render/render.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <sstream>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <optional>

#include "accel/accel_memory.h"
#include "film/film_stats.h"
#include "integrators/naive.h"
#include "integrators/path.h"
#include "integrators/surface_lanes.h"
#include "integrators/whitted.h"
#include "scene/volume_absorption.h"
#include "render/camera.h"
#include "render/pass_runner.h"
#include "render/pass_schedule.h"

namespace radiant {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// What camera rays that miss see: nothing in a transparent render; `blur` is the environment
// itself when it has no map to blur.
CameraBackground camera_background_of(const ResolvedSettings& s) {
  if (s.transparent) return CameraBackground::none;
  switch (s.background) {
    case BackgroundKind::blur:
      return s.environment.has_map() ? CameraBackground::backdrop : CameraBackground::environment;
    case BackgroundKind::environment: return CameraBackground::environment;
    case BackgroundKind::color: return CameraBackground::color;
    case BackgroundKind::transparent: break;
  }
  return CameraBackground::none;
}

RenderContext make_context(const PreparedScene& prepared, const ResolvedSettings& s, const LightTable& lights,
                           const RenderOptions& options, const CameraFrame& frame,
                           const TexturePyramids* pyramids) {
  const SceneDesc& scene = *prepared.scene;
  RenderContext ctx;
  ctx.scene = &scene;
  ctx.accel = prepared.accel.get();
  ctx.lights = &lights;
  for (const LightDesc& l : scene.lights)
    if (l.kind == LightKind::ambient) ctx.ambient += l.intensity;
  ctx.flat_materials.reserve(scene.materials.size());
  for (const MaterialDesc& m : scene.materials) ctx.flat_materials.push_back(resolve_material(scene, m, {}));
  ctx.flat_bsdf_materials.reserve(scene.materials.size());
  for (const SurfaceMaterial& m : ctx.flat_materials) ctx.flat_bsdf_materials.emplace_back(m);
  // Untextured; a textured render asks again at each hit (path.cpp, shade_in_surface_lanes).
  for (size_t i = 0; i < scene.materials.size(); ++i)
    ctx.lane_models.push_back(lane_model_of(ctx.flat_materials[i], ctx.flat_bsdf_materials[i]));
  // A texture scales the authored ks (resolve_material), so ks 0 stays 0 at every hit; kr is
  // not textured.
  for (const MaterialDesc& m : scene.materials)
    ctx.phong_lanes |= m.model == MaterialModel::phong && (max_component(m.ks) > 0 || max_component(m.kr) > 0);
  ctx.absorption.reserve(scene.materials.size());
  for (const MaterialDesc& m : scene.materials) ctx.absorption.push_back(volume_absorption(m));
  ctx.texture_lookup = {options.texture_filter, pyramids};
  ctx.pixel_spread = make_pixel_spread(frame);
  ctx.effects = s.effects;
  ctx.max_depth = s.max_depth;
  static_assert(max_indirect_paths <= max_batch_paths, "a batch holds every sub-path of a camera sample");
  ctx.split = s.indirect_paths;
  ctx.contribution_cutoff = options.contribution_cutoff;
  ctx.clamp_direct = options.clamp_direct, ctx.clamp_indirect = options.clamp_indirect;
  ctx.camera_background = camera_background_of(s);
  ctx.background_color = s.background_color;
  return ctx;
}

// What make_context's per-material tables take.
uint64_t shading_materials_bytes(const SceneDesc& scene) {
  return saturating_multiply(scene.materials.size(), sizeof(SurfaceMaterial) + sizeof(BsdfMaterial) + sizeof(color3));
}

Integrator select_integrator(const ResolvedSettings& s) {
  switch (s.mode) {
    case RenderMode::whitted: return select_whitted(s.compiled_variant);
    case RenderMode::naive: return select_naive(s.compiled_variant);
    case RenderMode::path:
    case RenderMode::auto_select: break;
  }
  return select_path(s.compiled_variant);
}

}  // namespace

RenderResult render_prepared(const PreparedScene& prepared, const RenderOptions& options) {
  RenderResult result;
  ResolvedSettings& s = result.settings;
  s = resolve_settings(prepared, options);
  int width = s.window.x1 - s.window.x0, height = s.window.y1 - s.window.y0;
  size_t channels = output_channel_names(options.aovs, s.transparent).size();
  // The denoiser reads the albedo, normal and depth sums and the two half images.
  bool want_aovs = !options.aovs.empty() || options.denoise;
  bool want_halves = options.denoise || wants_aov(options.aovs, "halves");
  result.image_memory = MemoryCharge(options.memory,
                                     render_image_bytes(width, height, channels, want_aovs, s.transparent, want_halves),
                                     prepared.scene->source_path + ": a " + std::to_string(width) + "x" +
                                         std::to_string(height) + " render with " + std::to_string(channels) +
                                         " channels (film, AOVs and output image)");
  bool path_like = s.mode != RenderMode::whitted;
  LightTable lights =
      make_light_table(*prepared.scene, s.environment, path_like, options.memory, options.light_sampler,
                       (s.effects & effect_textures) != 0);
  if (size_t negative = lights.environment_map.negative_texels) {
    std::ostringstream text;
    text << s.environment.map_path << ": " << negative << " negative pixel value(s), down to "
         << lights.environment_map.most_negative << ", read as 0";
    result.warnings.push_back(text.str());
  }
  s.light_sampler = lights.sampler;
  MemoryCharge materials_memory(options.memory, shading_materials_bytes(*prepared.scene),
                                prepared.scene->source_path + ": the materials prepared for shading");
  // A scene prepared for another filter builds the mip-maps this render needs for itself.
  std::unique_ptr<TexturePyramids> own_pyramids;
  const TexturePyramids* pyramids = prepared.texture_pyramids.get();
  if (options.texture_filter == TextureFilterMode::trilinear && !pyramids) {
    own_pyramids = std::make_unique<TexturePyramids>(build_texture_pyramids(*prepared.scene, options.memory));
    pyramids = own_pyramids.get();
  }
  CameraFrame frame = make_camera_frame(s.camera, s.width, s.height);
  RenderContext ctx = make_context(prepared, s, lights, options, frame, pyramids);

  tbb::task_arena arena(worker_threads(options.threads));
  arena.execute([&] { result.film = make_film(width, height, want_aovs, s.transparent, want_halves); });
  result.film.x = s.window.x0, result.film.y = s.window.y0;
  result.film.full_width = s.width, result.film.full_height = s.height;
  tbb::enumerable_thread_specific<RayCounts> counts;
  auto start = Clock::now();
  bool adaptive = options.noise_threshold > 0, timed = options.time_limit_seconds > 0;
  StopCheck stop;
  stop.request = options.stop_request;
  if (timed) {
    double limit = std::min(options.time_limit_seconds, max_time_limit_seconds);
    stop.deadline = options.deadline.value_or(
        start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limit)));
  }
  uint64_t pixels = uint64_t(width) * uint64_t(height);
  uint32_t range = s.samples.end - s.samples.begin;
  ProgressMeter progress(options.quiet ? ProgressStyle::none : options.progress, pixels * uint64_t(range), range,
                         stop.deadline);
  PixelFilter filter = make_pixel_filter(s.filter, s.filter_radius);
  PassRunner runner{ctx, s, select_integrator(s), frame, filter, want_aovs, s.transparent, want_halves,
                    options.path_batching, options.seed, result.film, counts, stop, progress};
  runner.motion_blur = (s.effects & effect_motion_blur) != 0;

  PassSchedule schedule;
  schedule.begin = s.samples.begin, schedule.end = s.samples.end;
  // Growing passes when a budget, a signal or a noise target may stop the render early, or when
  // someone watches the image sharpen; one pass otherwise.
  bool progressive = bool(options.on_pass);
  schedule.progressive = adaptive || timed || progressive || options.stop_request;
  if (adaptive) schedule.min_samples = adaptive_min_samples(options.noise_threshold, options.min_spp, uint32_t(s.spp));
  std::vector<uint8_t> unconverged, active;
  uint32_t done = s.samples.begin, total = s.samples.end;
  while (done < total) {
    uint32_t end = next_pass_end(schedule, done);
    if (timed && done > s.samples.begin) {
      // Passes that fit in the time left keep every pixel at the same number of samples.
      double remaining = std::chrono::duration<double>(*stop.deadline - Clock::now()).count();
      double per_sample = seconds_since(start) / (done - s.samples.begin);
      double fitting = std::max(0.0, remaining / (per_sample * 1.1));
      end = done + uint32_t(std::min<double>(end - done, fitting));
      if (end == done) {
        result.stats.stopped_by_time_limit = true;
        break;
      }
    }
    // The first pass always ends, so that a stopped render has a sample in every pixel.
    stop.armed = done > s.samples.begin || !options.stop_completes_first_pass;
    if (!stop.armed || !stop()) {
      arena.execute([&] { runner.run(done, end, active); });
      result.stats.passes++;
    }
    if (stop.stopped) {
      result.stats.interrupted = stop.requested();
      result.stats.stopped_by_time_limit = !result.stats.interrupted;
      break;
    }
    done = end;
    progress.set_samples_reached(done - s.samples.begin);
    if (progressive) options.on_pass(result.film, done);
    if (adaptive && done - s.samples.begin >= schedule.min_samples && done < total) {
      size_t remaining = 0;
      arena.execute([&] { remaining = mark_unconverged_pixels(result.film, options.noise_threshold, unconverged, active); });
      if (remaining == 0) break;
      progress.set_remaining(uint64_t(remaining) * (total - done));
    }
  }
  result.stats.samples_reached = done - s.samples.begin;
  result.stats.render_seconds = seconds_since(start);
  result.stats.build_seconds = prepared.build_seconds;
  for (const RayCounts& c : counts) result.stats.rays += c;
  result.stats.untraceable_rays = prepared.accel->untraceable_rays.exchange(0);

  FilmSampleStats film_stats;
  arena.execute([&] { film_stats = film_sample_stats(result.film); });
  result.stats.samples = film_stats.samples;
  result.stats.min_pixel_samples = film_stats.min_pixel_samples;
  result.stats.median_pixel_samples = film_stats.median_pixel_samples;
  result.stats.p90_pixel_samples = film_stats.p90_pixel_samples;
  result.stats.max_pixel_samples = film_stats.max_pixel_samples;
  result.stats.estimated_relative_error = film_stats.mean_relative_error;
  return result;
}

int worker_threads(int requested) {
  // More threads than TBB's limit (the cores) are not started anyway, and asking prints a warning.
  int cores = tbb::this_task_arena::max_concurrency();
  return requested > 0 ? std::min(requested, cores) : cores;
}

void set_output_encoding(OutputImage& image, const RenderOptions& options, const ResolvedSettings& settings) {
  image.display = {options.exposure, settings.view};
  image.bit_depth = options.bit_depth;
  image.half = options.half_float;
}

}  // namespace radiant
