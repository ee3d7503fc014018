// The film: per-pixel sums of radiance samples and their squares, plus first-hit AOVs.
// Each pixel is written by one thread at a time, in sample order, so results are deterministic.
#pragma once

#include <cstdint>
#include <vector>

#include "math/vec.h"

namespace radiant {

struct FilmPixel {
  double sum[3] = {0, 0, 0};
  double sum_squares[3] = {0, 0, 0};
  uint32_t samples = 0;
  // First-hit auxiliary values, summed in double like the radiance: float sums of large finite
  // values (an albedo or a depth near 1e38) would overflow to infinity.
  double albedo[3] = {0, 0, 0};
  double normal[3] = {0, 0, 0};
  double depth = 0;
};

struct Film {
  int width = 0, height = 0;
  std::vector<FilmPixel> pixels;
  FilmPixel& at(int x, int y) { return pixels[size_t(y) * width + x]; }
  const FilmPixel& at(int x, int y) const { return pixels[size_t(y) * width + x]; }
};

Film make_film(int width, int height);

inline void add_sample(FilmPixel& p, color3 radiance) {
  for (int c = 0; c < 3; ++c) {
    p.sum[c] += radiance[c];
    p.sum_squares[c] += double(radiance[c]) * radiance[c];
  }
  p.samples++;
}

// Mean radiance of a pixel (black without samples).
color3 pixel_mean(const FilmPixel& p);
// Variance of the pixel mean (sample variance / samples), per channel. It saturates at the
// largest float, which only pixels whose mean exceeds ~1.8e19 reach: the value written is
// always finite, and a smaller variance only makes a comparison stricter.
color3 pixel_mean_variance(const FilmPixel& p);

}  // namespace radiant
