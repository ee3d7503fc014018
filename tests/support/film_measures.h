// Summary numbers of rendered films that tests bound: mean brightness, RMS difference, and a
// z-score for "same expectation, within the noise".
#pragma once

#include <algorithm>
#include <cmath>

#include "render/render.h"

namespace radiant::test {

inline double mean_luminance(const Film& film) {
  double sum = 0;
  for (const FilmPixel& p : film.pixels) sum += luminance(pixel_mean(p));
  return sum / double(film.pixels.size());
}

// RMS of the pixel differences between two films of the same size.
inline double rms_difference(const Film& a, const Film& b) {
  double sum = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    color3 d = pixel_mean(a.pixels[i]) - pixel_mean(b.pixels[i]);
    sum += double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z;
  }
  return std::sqrt(sum / double(3 * a.pixels.size()));
}

// Largest |difference| / standard error between the two films' means over 8x8-pixel blocks, per
// channel: under equal expectations each is about normal with unit variance.
inline double largest_block_z(const Film& a, const Film& b) {
  double largest = 0;
  for (int by = 0; by < a.height; by += 8)
    for (int bx = 0; bx < a.width; bx += 8)
      for (int c = 0; c < 3; ++c) {
        double mean_a = 0, mean_b = 0, variance = 0;
        for (int y = by; y < by + 8; ++y)
          for (int x = bx; x < bx + 8; ++x) {
            mean_a += pixel_mean(a.at(x, y))[c], mean_b += pixel_mean(b.at(x, y))[c];
            variance += double(pixel_mean_variance(a.at(x, y))[c]) + double(pixel_mean_variance(b.at(x, y))[c]);
          }
        largest = std::max(largest, std::abs(mean_a - mean_b) / std::sqrt(std::max(variance, 1e-30)));
      }
  return largest;
}

}  // namespace radiant::test
