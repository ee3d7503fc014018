// Rendering a prepared scene: settings resolution, the passes over the film, statistics.
#pragma once

#include <memory>
#include <string>

#include "film/film.h"
#include "image/image_writer.h"
#include "integrators/render_context.h"
#include "lights/light_table.h"
#include "render/output_image.h"
#include "render/prepared_scene.h"
#include "render/render_options.h"
#include "render/resolved_settings.h"

namespace radiant {

// Throws std::invalid_argument for settings that make no sense (names the flag). The camera is
// resolved in world space and placed in the prepared scene's render space.
ResolvedSettings resolve_settings(const PreparedScene& prepared, const RenderOptions& options);

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

// How the image is to be stored, as the options ask: exposure, the resolved view transform, bit
// depth and half floats (src/image/view_transform.h).
void set_output_encoding(OutputImage& image, const RenderOptions& options, const ResolvedSettings& settings);

}  // namespace radiant
