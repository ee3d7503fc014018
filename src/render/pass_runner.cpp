#include "render/pass_runner.h"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "integrators/path.h"
#include "scene/motion_steps.h"

namespace radiant {

std::optional<Ray> PassRunner::camera_ray(int x, int y, const SampleContext& sample, vec2 pixel_pair, bool& negative) const {
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

void PassRunner::add_sample_to_film(int x, int y, uint32_t index, color3 value, const FirstHit& first_hit, bool negative,
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

void PassRunner::render_pixel(int x, int y, uint32_t first, uint32_t end) const {
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

void PassRunner::render_tile_batched(const tbb::blocked_range2d<int>& r, uint32_t first, uint32_t end,
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
  bool pairs = sampler_extends(s.sampler);  // drawn per sample; grid and jittered by their strata
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

void PassRunner::run(uint32_t first, uint32_t end, const std::vector<uint8_t>& active) const {
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

}  // namespace radiant
