#include "render/render.h"

#include <tbb/blocked_range2d.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
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
#include "scene/scene_motion.h"
#include "scene/volume_absorption.h"
#include "render/camera.h"
#include "render/pass_schedule.h"
#include "render/progress_meter.h"
#include "render/stroke_sizing.h"
#include "sampling/pixel_filter.h"

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

// Whether the render must stop before its samples are all taken: checked before every pixel once
// armed (after the first pass), so a stop lands within one pixel's samples of a pass at any image
// size. Once one thread sees it, every thread does, and the film keeps exactly the samples taken.
struct StopCheck {
  const std::atomic<int>* request = nullptr;  // a signal
  std::optional<Clock::time_point> deadline;  // the time limit
  std::atomic<bool> armed{true};              // false: the pass under way ends whatever is asked
  mutable std::atomic<bool> stopped{false};

  bool requested() const { return request && request->load(std::memory_order_relaxed) != 0; }
  bool operator()() const {
    if (stopped.load(std::memory_order_relaxed)) return true;
    if (!armed.load(std::memory_order_relaxed)) return false;
    if (!requested() && (!deadline || Clock::now() < *deadline)) return false;
    stopped.store(true, std::memory_order_relaxed);
    return true;
  }
};

struct PassRunner {
  const RenderContext& ctx;
  const ResolvedSettings& s;
  Integrator integrator;
  CameraFrame frame;
  const PixelFilter& filter;
  bool want_aovs;
  bool want_coverage;  // a transparent render
  bool want_halves;    // the odd samples summed apart, for the denoiser
  PathBatching batching;
  uint32_t seed;
  Film& film;
  tbb::enumerable_thread_specific<RayCounts>& counts;
  const StopCheck& stop;
  ProgressMeter& progress;
  // Camera rays spread over the shutter (effect_motion_blur): each draws its time.
  bool motion_blur = false;

  // The camera ray of sample `sample` at pixel (x, y) through `pixel_pair` (its sample_pixel), and
  // the filter's weight sign; none where the projection sees nothing (outside a fisheye's circle).
  std::optional<Ray> camera_ray(int x, int y, const SampleContext& sample, vec2 pixel_pair, bool& negative) const {
    // The pixel pair warped by the filter: the box of one pixel keeps it as it is.
    FilterSample placed = sample_filter(filter, pixel_pair);
    negative = placed.weight < 0;  // the weight's magnitude is one for the whole filter
    vec2 lens = frame.lens_radius > 0 ? sample_2d(sample, lens_dimension) : vec2{0.5f, 0.5f};
    if (!motion_blur) return generate_camera_ray(frame, float(x) + placed.position.x, float(y) + placed.position.y, lens);
    float time = sample_time(sample);
    CameraFrame moved = s.camera.motion.empty() ? frame : move_camera_frame(frame, pose_at_time(s.camera.motion, time));
    std::optional<Ray> ray = generate_camera_ray(moved, float(x) + placed.position.x, float(y) + placed.position.y, lens);
    if (ray) ray->time = time;
    return ray;
  }

  SampleContext sample_at(int x, int y, uint32_t index) const {
    return {s.sampler, uint32_t(y) * uint32_t(s.width) + uint32_t(x), index, uint32_t(s.spp), seed};
  }

  // Sample `index`'s radiance and AOV values added to pixel (x, y); a non-finite sample is dropped.
  void add_sample_to_film(int x, int y, uint32_t index, color3 value, const FirstHit& first_hit, bool negative,
                          RayCounts& c) const {
    if (!is_finite(value) || (want_aovs && !is_finite(first_hit))) {
      c.nonfinite_samples++;  // dropped, AOVs and all: never reaches the film
      return;
    }
    size_t film_index = size_t(y - s.window.y0) * film.width + (x - s.window.x0);
    add_sample(film.pixels[film_index], value, negative);
    if (want_halves && (index & 1)) add_half_sample(film.odd_half[film_index], value, negative);
    if (want_coverage) film.alpha[film_index].add(negative ? -first_hit.coverage : first_hit.coverage);
    if (want_aovs) {
      FilmAovs& a = film.aovs[film_index];
      for (int k = 0; k < 3; ++k) {
        a.albedo[k].add(first_hit.albedo[k]);
        a.normal[k].add(first_hit.normal[k]);
      }
      a.depth.add(first_hit.depth);
    }
  }

  FirstHit* first_hit_wanted(FirstHit& first_hit) const { return want_aovs || want_coverage ? &first_hit : nullptr; }

  void render_pixel(int x, int y, uint32_t first, uint32_t end) const {
    RayCounts& c = counts.local();
    for (uint32_t index = first; index < end; ++index) {
      SampleContext sample = sample_at(x, y, index);
      bool negative;
      std::optional<Ray> ray = camera_ray(x, y, sample, sample_pixel(sample), negative);
      FirstHit first_hit;
      color3 value =
          ray ? integrator.one_path(ctx, *ray, sample, c, first_hit_wanted(first_hit), nullptr) : color3{};
      add_sample_to_film(x, y, index, value, first_hit, negative, c);
    }
  }

  bool is_active(const std::vector<uint8_t>& active, int x, int y) const {
    return active.empty() || active[size_t(y - s.window.y0) * film.width + (x - s.window.x0)];
  }

  // A tile a few samples at a time (batch_samples): their camera rays, coherent across the tile,
  // are traced together as packets (one at a time where Embree calls back: analytic shapes,
  // alpha masks); the paths go on from their hits alone, or as a batch (all_rays). Every pixel gets the same samples, in the same order, as render_pixel gives it,
  // and each the same value. Each finished 8x8 tile counts for the progress line at once: one
  // thread's range may hold many tiles, and a line that moved only per range stood still for
  // seconds.
  void render_tile_batched(const tbb::blocked_range2d<int>& r, uint32_t first, uint32_t end,
                                const std::vector<uint8_t>& active) const {
    static_assert(batch_tile_pixels >= 64, "a batch holds the largest tile run() makes: grain 8 x 8");
    struct Pending {
      int x, y;
      uint32_t index;  // the sample's
      bool negative;
      int path;  // its index in the batch, or -1 where the camera sees nothing
      FirstHit first_hit;
    };
    // One per thread, held by a static object rather than in TLS (see PathVariant::run_batch).
    struct Workspace {
      Pending tile[batch_tile_pixels];  // the tile's active pixels
      Pending pending[max_batch_paths];  // a batch's samples: the tile's pixels once per sample
      BatchPath batch[max_batch_paths];
      const Ray* rays[max_batch_paths];
      HitId hits[max_batch_paths];
      // The Sobol and random samplers' pixel pairs (dimension 0, as sample_pixel draws them), a
      // tile's at once; the grid and jittered samplers' positions, with the tile's pixel numbers
      // they are drawn for.
      SampleLanes pixel_pairs;
      uint32_t tile_pixel[batch_tile_pixels];
      float stratified_x[batch_tile_pixels], stratified_y[batch_tile_pixels];
    };
    static_assert(SampleLanes::capacity >= batch_tile_pixels);
    static tbb::enumerable_thread_specific<Workspace> per_thread;
    auto& [tile, pending, batch, rays, hits, pixel_pairs, tile_pixel, stratified_x, stratified_y] = per_thread.local();
    bool pairs = s.sampler == SamplerKind::sobol || s.sampler == SamplerKind::random;  // or grid, jittered
    RayCounts& c = counts.local();
    for (int y0 = r.rows().begin(); y0 < r.rows().end(); y0 += 8)
      for (int x0 = r.cols().begin(); x0 < r.cols().end(); x0 += 8) {
        int count = 0;
        for (int y = y0; y < std::min(y0 + 8, r.rows().end()); ++y)
          for (int x = x0; x < std::min(x0 + 8, r.cols().end()); ++x)
            if (is_active(active, x, y)) tile[count++] = {x, y, 0, false, -1, {}};
        for (int i = 0; i < count; ++i) tile_pixel[i] = sample_at(tile[i].x, tile[i].y, 0).pixel;
        for (uint32_t batch_first = first; batch_first < end; batch_first += batch_samples) {
          if (stop()) return;
          uint32_t batch_end = std::min(end, batch_first + batch_samples);
          int paths = 0, samples = 0;
          for (uint32_t index = batch_first; index < batch_end; ++index) {
            if (pairs) {
              pixel_pairs.count = 0;
              for (int i = 0; i < count; ++i) pixel_pairs.add(sample_at(tile[i].x, tile[i].y, index), 0);
              draw_sample_lanes(s.sampler, pixel_pairs);
            } else {
              draw_stratified_pixels(s.sampler, uint32_t(s.spp), index, seed, tile_pixel, count, stratified_x,
                                     stratified_y);
            }
            for (int i = 0; i < count; ++i) {
              Pending& p = pending[samples++];
              p = tile[i];
              p.index = index;
              SampleContext sample = sample_at(p.x, p.y, index);
              vec2 pixel_pair = pairs ? vec2{pixel_pairs.x[i], pixel_pairs.y[i]} : vec2{stratified_x[i], stratified_y[i]};
              std::optional<Ray> ray = camera_ray(p.x, p.y, sample, pixel_pair, p.negative);
              p.path = ray ? paths : -1;
              if (ray) {
                BatchPath& path = batch[paths];
                path.ray = *ray;
                path.sample = sample;
                path.first_hit = first_hit_wanted(p.first_hit);
                rays[paths++] = &path.ray;
              }
            }
          }
          intersect_nearest_many(*ctx.accel, rays, paths, hits, RayCoherence::coherent, camera_culling(ctx));
          for (int k = 0; k < paths; ++k) batch[k].camera_hit = hits[k];
          if (batching == PathBatching::all_rays)
            integrator.batch(ctx, batch, paths, c);
          else
            run_each_path(integrator.one_path, ctx, batch, paths, c);
          for (int i = 0; i < samples; ++i) {
            const Pending& p = pending[i];
            add_sample_to_film(p.x, p.y, p.index, p.path >= 0 ? batch[p.path].radiance : color3{}, p.first_hit, p.negative, c);
          }
        }
        progress.add(uint64_t(count) * (end - first));
      }
  }

  // Adds samples [first, end) to every pixel still active, until told to stop.
  void run(uint32_t first, uint32_t end, const std::vector<uint8_t>& active) const {
    const PixelWindow& w = s.window;
    bool batched = batching != PathBatching::none;
    tbb::parallel_for(tbb::blocked_range2d<int>(w.y0, w.y1, 8, w.x0, w.x1, 8), [&](const tbb::blocked_range2d<int>& r) {
      if (batched) {
        render_tile_batched(r, first, end, active);
        return;
      }
      uint64_t rendered = 0;
      for (int y = r.rows().begin(); y < r.rows().end(); ++y)
        for (int x = r.cols().begin(); x < r.cols().end(); ++x) {
          if (stop()) return;
          if (is_active(active, x, y)) render_pixel(x, y, first, end), ++rendered;
        }
      progress.add(rendered * (end - first));
    });
  }
};

// The image's width / height as a camera without an aspect of its own will see it (1 when the
// size comes from the default).
float image_aspect(const SceneSettings& settings, const RenderOptions& options) {
  // One side from the flags keeps the scene's shape (resolve_settings).
  bool flags = options.width && options.height;
  std::optional<int> width = flags ? options.width : settings.width;
  std::optional<int> height = flags ? options.height : settings.height;
  return width && height && *width > 0 && *height > 0 ? float(*width) / float(*height) : 1.0f;
}

}  // namespace

void build_accel(PreparedScene& prepared) {
  prepared.accel.reset();
  prepared.accel_memory = MemoryCharge();
  prepared.accel_memory = MemoryCharge(prepared.budget, accel_build_bytes(*prepared.scene),
                                       prepared.scene->source_path + ": the accelerator");
  auto start = Clock::now();
  prepared.accel = build_scene_accel(*prepared.scene, prepared.layout, prepared.stroke_sizing);
  prepared.build_seconds = seconds_since(start);
}

CameraDesc world_view_camera(const PreparedScene& prepared, const RenderOptions& options, bool& framed) {
  return world_view_camera(prepared.world, prepared.scene->settings, options, framed);
}

CameraDesc world_view_camera(const WorldPlacement& world, const SceneSettings& settings, const RenderOptions& options,
                             bool& framed) {
  CameraDesc framing;
  framing.name = "framing";
  vec3 up = options.world_up ? normalize(*options.world_up) : vec3{0, 1, 0};
  if (world.has_framing_box)
    framing = frame_box(world.framing_lower, world.framing_upper, image_aspect(settings, options), up,
                        options.orbit.value_or(Orbit{}));
  // --orbit turns the framing camera, which it takes unless another is named.
  std::string which = options.orbit && options.camera.empty() ? framing_camera_name : options.camera;
  CameraDesc camera = select_camera(world.cameras, framing, which, framed);
  if (options.orbit && !framed)
    throw std::invalid_argument("--orbit turns the framing camera: leave out --camera, or give --camera frame");
  bool made_orthographic = camera.projection != Projection::orthographic &&
                           options.camera_override.projection == Projection::orthographic;
  apply_camera_override(camera, options.camera_override);
  // A view turned orthographic by the flags shows the whole scene, as the framing camera does.
  if (made_orthographic && world.has_framing_box)
    frame_orthographic(camera, world.framing_lower, world.framing_upper, image_aspect(settings, options),
                       options.camera_override.look_from.has_value(), options.camera_override.ortho_height.has_value());
  // A camera placed entirely by the flags is not a framing camera.
  if (options.camera_override.look_from && options.camera_override.look_at) framed = false;
  return camera;
}

// How the view of `options` sizes the prepared scene's lines and points.
static StrokeSizing view_stroke_sizing(const PreparedScene& prepared, const RenderOptions& options) {
  if (prepared.scene->strokes.empty() || !options.line_width.in_pixels) return {options.line_width, {}};
  bool framed = false;
  CameraDesc camera = world_view_camera(prepared, options, framed);
  int height = resolved_image_height(options, *prepared.scene, camera);
  return stroke_sizing_for(*prepared.scene, options.line_width, camera, height, prepared.origin);
}

PreparedScene prepare_scene(SceneDesc scene, const RenderOptions& options, AccelLayout layout) {
  // Without motion blur the scene holds still at the rendered time.
  if (!(apply_effects_override(effect_motion_blur, options.effects) & effect_motion_blur)) drop_motion(scene);
  PreparedScene prepared;
  prepared.budget = options.memory;
  prepared.layout = layout;
  prepared.world = record_world_placement(scene);
  prepared.scene = std::make_unique<SceneDesc>(std::move(scene));
  bool framed = false;
  prepared.origin = choose_render_origin(prepared.world, world_view_camera(prepared, options, framed).position);
  place_at_render_origin(*prepared.scene, prepared.world, prepared.origin);
  prepared.stroke_sizing = view_stroke_sizing(prepared, options);
  build_accel(prepared);
  prepared.effects = analyze_effects(*prepared.scene);
  if (options.texture_filter == TextureFilterMode::trilinear)
    prepared.texture_pyramids = std::make_unique<TexturePyramids>(build_texture_pyramids(*prepared.scene, options.memory));
  return prepared;
}

double prepare_view(PreparedScene& prepared, const RenderOptions& options) {
  bool framed = false;
  dvec3 origin = choose_render_origin(prepared.world, world_view_camera(prepared, options, framed).position);
  bool moved = origin.x != prepared.origin.x || origin.y != prepared.origin.y || origin.z != prepared.origin.z;
  if (moved) {
    prepared.origin = origin;
    place_at_render_origin(*prepared.scene, prepared.world, origin);
  }
  // Lines and points a number of pixels wide follow the view.
  StrokeSizing sizing = view_stroke_sizing(prepared, options);
  if (!moved && same_sizing(sizing, prepared.stroke_sizing)) return 0;
  prepared.stroke_sizing = sizing;
  build_accel(prepared);
  return prepared.build_seconds;
}

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

bool wants_aov(const std::vector<std::string>& aovs, const std::string& name) {
  return std::find(aovs.begin(), aovs.end(), name) != aovs.end();
}

int worker_threads(int requested) {
  // More threads than TBB's limit (the cores) are not started anyway, and asking prints a warning.
  int cores = tbb::this_task_arena::max_concurrency();
  return requested > 0 ? std::min(requested, cores) : cores;
}

uint64_t render_image_bytes(int width, int height, size_t channels, bool with_aovs, bool with_alpha, bool with_halves) {
  // A film pixel (with its AOV, coverage and half-image sums when kept), a sample count and two
  // activity bytes (adaptive sampling's verdict on the pixel and on its neighbourhood); the
  // output image's floats; for 8-bit formats three more floats a pixel (four with alpha) and
  // three bytes a channel: the PNG encoder's filtered rows, its compressed pieces and the file
  // they make (deflate's output exceeds its input by a fraction of a percent at most, which the
  // pixel's other bytes cover).
  uint64_t display_channels = with_alpha ? 4 : 3;
  uint64_t per_pixel = film_pixel_bytes(with_aovs, with_alpha, with_halves) + sizeof(uint32_t) + 2 + channels * sizeof(float) +
                       display_channels * (sizeof(float) + 3);
  return saturating_multiply(uint64_t(std::max(width, 0)) * uint64_t(std::max(height, 0)), per_pixel);
}

std::vector<std::string> output_channel_names(const std::vector<std::string>& aovs, bool with_alpha) {
  std::vector<std::string> channels = {"R", "G", "B"};
  if (with_alpha) channels.push_back("A");
  for (const std::string& aov : aovs) {
    if (aov == "albedo") channels.insert(channels.end(), {"albedo.R", "albedo.G", "albedo.B"});
    else if (aov == "normal") channels.insert(channels.end(), {"N.X", "N.Y", "N.Z"});
    else if (aov == "depth") channels.push_back("Z");
    else if (aov == "variance") channels.insert(channels.end(), {"variance.R", "variance.G", "variance.B"});
    else if (aov == "spp") channels.push_back("spp");
    else if (aov == "noisy") channels.insert(channels.end(), {"noisy.R", "noisy.G", "noisy.B"});
    else if (aov == "halves") channels.insert(channels.end(), {"even.R", "even.G", "even.B", "odd.R", "odd.G", "odd.B"});
  }
  return channels;
}

void set_output_encoding(OutputImage& image, const RenderOptions& options, const ResolvedSettings& settings) {
  image.display = {options.exposure, settings.view};
  image.bit_depth = options.bit_depth;
  image.half = options.half_float;
}

OutputImage film_to_image(const Film& film, const std::vector<std::string>& aovs) {
  OutputImage image;
  image.width = film.width;
  image.height = film.height;
  image.x = film.x, image.y = film.y;
  image.full_width = film.full_width, image.full_height = film.full_height;
  bool with_alpha = !film.alpha.empty();
  image.channels = output_channel_names(aovs, with_alpha);
  size_t stride = image.channels.size();
  image.pixels.resize(size_t(film.width) * film.height * stride);
  // Each pixel's exact sums resolved on every thread: a large image's resolve would otherwise be
  // a serial tail after the render.
  tbb::parallel_for(size_t(0), film.pixels.size(), [&](size_t i) {
    const FilmPixel& p = film.pixels[i];
    float* out = &image.pixels[i * stride];
    color3 mean = pixel_mean(p);
    *out++ = mean.x, *out++ = mean.y, *out++ = mean.z;
    if (with_alpha) *out++ = pixel_alpha(film, i);
    static const FilmAovs no_aovs;  // a film made without AOV sums gives black AOVs
    const FilmAovs& a = film.aovs.empty() ? no_aovs : film.aovs[i];
    for (const std::string& aov : aovs) {
      if (aov == "albedo") {
        color3 albedo = pixel_albedo(p, a);
        *out++ = albedo.x, *out++ = albedo.y, *out++ = albedo.z;
      } else if (aov == "normal") {
        vec3 normal = pixel_normal(a);
        *out++ = normal.x, *out++ = normal.y, *out++ = normal.z;
      } else if (aov == "depth") *out++ = pixel_depth(p, a);
      else if (aov == "variance") {
        color3 v = pixel_mean_variance(p);
        *out++ = v.x, *out++ = v.y, *out++ = v.z;
      } else if (aov == "spp") *out++ = float(p.samples);
      else if (aov == "noisy") *out++ = mean.x, *out++ = mean.y, *out++ = mean.z;
      else if (aov == "halves") {
        color3 even = mean, odd = mean;  // a film without halves: both are the whole pixel
        if (!film.odd_half.empty()) pixel_half_means(p, film.odd_half[i], even, odd);
        for (int k = 0; k < 3; ++k) *out++ = even[k];
        for (int k = 0; k < 3; ++k) *out++ = odd[k];
      }
    }
  });
  return image;
}

}  // namespace radiant
