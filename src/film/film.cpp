#include "film/film.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>

namespace radiant {

Film make_film(int width, int height, bool with_aovs, bool with_alpha, bool with_halves) {
  Film film;
  film.width = width;
  film.height = height;
  film.full_width = width;
  film.full_height = height;
  size_t count = size_t(width) * height;
  film.pixels.resize(count);
  if (with_aovs) film.aovs.resize(count);
  if (with_alpha) film.alpha.resize(count);
  if (with_halves) film.odd_half.resize(count);
  // FilmAllocator left every element unconstructed: each thread constructs (and first touches)
  // rows of pages of its own.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 4096), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t i = range.begin(); i < range.end(); ++i) {
      ::new (static_cast<void*>(&film.pixels[i])) FilmPixel();
      if (with_aovs) ::new (static_cast<void*>(&film.aovs[i])) FilmAovs();
      if (with_alpha) ::new (static_cast<void*>(&film.alpha[i])) ExactSum();
      if (with_halves) ::new (static_cast<void*>(&film.odd_half[i])) FilmHalf();
    }
  });
  return film;
}

void add_pixel(FilmPixel& to, const FilmPixel& from) {
  for (int c = 0; c < 3; ++c) {
    to.sum[c].add(from.sum[c]);
    to.sum_squares[c].add(from.sum_squares[c]);
  }
  to.samples += from.samples;
  to.negative_samples += from.negative_samples;
}

void add_aovs(FilmAovs& to, const FilmAovs& from) {
  for (int c = 0; c < 3; ++c) {
    to.albedo[c].add(from.albedo[c]);
    to.normal[c].add(from.normal[c]);
  }
  to.depth.add(from.depth);
}

void add_half(FilmHalf& to, const FilmHalf& from) {
  for (int c = 0; c < 3; ++c) to.sum[c].add(from.sum[c]);
  to.samples += from.samples;
  to.negative_samples += from.negative_samples;
}

void pixel_half_means(const FilmPixel& p, const FilmHalf& odd, color3& even_mean, color3& odd_mean) {
  color3 whole = pixel_mean(p);
  double odd_weight = double(odd.samples) - 2.0 * double(odd.negative_samples);
  double even_weight = pixel_weight(p) - odd_weight;
  for (int c = 0; c < 3; ++c) {
    double odd_sum = odd.sum[c].value(), even_sum = p.sum[c].value() - odd_sum;
    odd_mean[c] = odd_weight != 0 ? float(odd_sum / odd_weight) : whole[c];
    even_mean[c] = even_weight != 0 ? float(even_sum / even_weight) : whole[c];
  }
}

color3 pixel_mean(const FilmPixel& p) {
  double weight = pixel_weight(p);  // the sample count, exactly, without negative weights
  if (weight == 0) return {0, 0, 0};
  return {float(p.sum[0].value() / weight), float(p.sum[1].value() / weight), float(p.sum[2].value() / weight)};
}

color3 pixel_albedo(const FilmPixel& p, const FilmAovs& a) {
  double n = p.samples ? double(p.samples) : 1.0;
  return {float(a.albedo[0].value() / n), float(a.albedo[1].value() / n), float(a.albedo[2].value() / n)};
}

vec3 pixel_normal(const FilmAovs& a) {
  return normalize(vec3{float(a.normal[0].value()), float(a.normal[1].value()), float(a.normal[2].value())});
}

float pixel_depth(const FilmPixel& p, const FilmAovs& a) {
  return float(a.depth.value() / (p.samples ? double(p.samples) : 1.0));
}

float pixel_alpha(const Film& film, size_t i) {
  double weight = pixel_weight(film.pixels[i]);
  return weight != 0 ? float(film.alpha[i].value() / weight) : 0.0f;
}

color3 pixel_mean_variance(const FilmPixel& p) {
  if (p.samples < 2) return {0, 0, 0};
  double n = p.samples, weight = pixel_weight(p);
  if (weight == 0) return color3{1, 1, 1} * std::numeric_limits<float>::max();  // no mean to be sure of
  // The mean divides by the weight, not the count: its variance grows by (n / weight)^2 (exactly
  // 1 without negative weights).
  double scale = (n / weight) * (n / weight);
  color3 v;
  for (int c = 0; c < 3; ++c) {
    double mean = p.sum[c].value() / n;
    double sample_variance = std::max(0.0, (p.sum_squares[c].value() - n * mean * mean) / (n - 1));
    v[c] = float(std::min(sample_variance / n * scale, double(std::numeric_limits<float>::max())));
  }
  return v;
}

}  // namespace radiant
