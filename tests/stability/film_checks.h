// Checks every stability render goes through: no NaN or Inf anywhere, and films compared pixel
// by pixel with summary numbers a test can bound.
#pragma once

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "support/scene_builders.h"

namespace radiant::test {

// Renders in-process and asserts that no pixel mean is NaN or Inf and that the integrator
// produced no non-finite sample at all (the film drops them, `nonfinite_samples` counts them).
inline RenderResult render_finite(const SceneDesc& scene, const RenderOptions& options) {
  RenderResult result = render_scene(scene, options);
  size_t nonfinite_pixels = 0;
  for (const FilmPixel& p : result.film.pixels) nonfinite_pixels += !is_finite(pixel_mean(p));
  CHECK(nonfinite_pixels == 0);
  CHECK(result.stats.rays.nonfinite_samples == 0);
  return result;
}

// Whitted at `size` x `size` pixels, `spp` samples (one sample goes through the pixel centre).
inline RenderOptions whitted_options(int size, int spp = 1) {
  RenderOptions o;
  o.width = size;
  o.height = size;
  o.spp = spp;
  o.mode = RenderMode::whitted;
  return o;
}

inline RenderOptions path_options(int size, int spp, int max_depth) {
  RenderOptions o;
  o.width = size;
  o.height = size;
  o.spp = spp;
  o.max_depth = max_depth;
  o.mode = RenderMode::path;
  return o;
}

struct FilmDifference {
  double mean_absolute = 0;        // over pixels and channels
  double max_absolute = 0;
  double fraction_over = 0;        // pixels where some channel differs by more than the threshold
};

// Per-pixel difference of two films of the same size; `threshold` is relative to `reference`'s
// channel value with a floor of `absolute_floor` (so black pixels do not make it infinitely tight).
inline FilmDifference compare_films(const Film& reference, const Film& other, double threshold,
                                    double absolute_floor) {
  FilmDifference d;
  REQUIRE(reference.pixels.size() == other.pixels.size());
  size_t over = 0;
  for (size_t i = 0; i < reference.pixels.size(); ++i) {
    color3 a = pixel_mean(reference.pixels[i]), b = pixel_mean(other.pixels[i]);
    bool differs = false;
    for (int c = 0; c < 3; ++c) {
      double e = std::abs(double(a[c]) - double(b[c]));
      d.mean_absolute += e;
      d.max_absolute = std::max(d.max_absolute, e);
      differs |= e > threshold * std::max(double(std::abs(a[c])), absolute_floor);
    }
    over += differs;
  }
  d.mean_absolute /= 3.0 * double(reference.pixels.size());
  d.fraction_over = double(over) / double(reference.pixels.size());
  return d;
}

}  // namespace radiant::test
