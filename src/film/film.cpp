#include "film/film.h"

#include <algorithm>
#include <limits>

namespace radiant {

Film make_film(int width, int height) {
  Film film;
  film.width = width;
  film.height = height;
  film.pixels.resize(size_t(width) * height);
  return film;
}

color3 pixel_mean(const FilmPixel& p) {
  if (p.samples == 0) return {0, 0, 0};
  double n = p.samples;
  return {float(p.sum[0] / n), float(p.sum[1] / n), float(p.sum[2] / n)};
}

color3 pixel_mean_variance(const FilmPixel& p) {
  if (p.samples < 2) return {0, 0, 0};
  double n = p.samples;
  color3 v;
  for (int c = 0; c < 3; ++c) {
    double mean = p.sum[c] / n;
    double sample_variance = std::max(0.0, (p.sum_squares[c] - n * mean * mean) / (n - 1));
    v[c] = float(std::min(sample_variance / n, double(std::numeric_limits<float>::max())));
  }
  return v;
}

}  // namespace radiant
