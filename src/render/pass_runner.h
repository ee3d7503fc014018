// One pass of a render: samples [first, end) added to every pixel still active, tile by tile on
// every thread, path by path or as batches, until told to stop.
#pragma once

#include <tbb/blocked_range2d.h>
#include <tbb/enumerable_thread_specific.h>

#include <atomic>
#include <chrono>
#include <optional>
#include <vector>

#include "film/film.h"
#include "integrators/render_context.h"
#include "render/camera.h"
#include "render/progress_meter.h"
#include "render/resolved_settings.h"
#include "sampling/pixel_filter.h"

namespace radiant {

// Whether the render must stop before its samples are all taken: checked before every pixel once
// armed (after the first pass), so a stop lands within one pixel's samples of a pass at any image
// size. Once one thread sees it, every thread does, and the film keeps exactly the samples taken.
struct StopCheck {
  using Clock = std::chrono::steady_clock;
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
  std::optional<Ray> camera_ray(int x, int y, const SampleContext& sample, vec2 pixel_pair, bool& negative) const;

  SampleContext sample_at(int x, int y, uint32_t index) const {
    return {s.sampler, uint32_t(y) * uint32_t(s.width) + uint32_t(x), index, uint32_t(s.spp), seed};
  }

  // Sample `index`'s radiance and AOV values added to pixel (x, y); a non-finite sample is dropped.
  void add_sample_to_film(int x, int y, uint32_t index, color3 value, const FirstHit& first_hit, bool negative,
                          RayCounts& c) const;

  FirstHit* first_hit_wanted(FirstHit& first_hit) const { return want_aovs || want_coverage ? &first_hit : nullptr; }

  void render_pixel(int x, int y, uint32_t first, uint32_t end) const;

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
                           const std::vector<uint8_t>& active) const;

  // Adds samples [first, end) to every pixel still active, until told to stop.
  void run(uint32_t first, uint32_t end, const std::vector<uint8_t>& active) const;
};

}  // namespace radiant
