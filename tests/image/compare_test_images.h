// Small images for the comparison tests.
#pragma once

#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/test_support.h"

namespace radiant::test {

inline void write_rgb(const std::filesystem::path& path, int width, int height,
                      const std::vector<float>& values) {
  write_test_image(path, width, height, {"R", "G", "B"}, values);
}

// A width×height RGB ramp with values in [0.2, 0.8]: no black, no clipping.
inline std::vector<float> ramp_rgb(int width, int height) {
  std::vector<float> values;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c)
        values.push_back(0.2f + 0.6f * float(x + y + c) / float(width + height + 1));
  return values;
}

inline std::vector<float> scaled(std::vector<float> values, float scale) {
  for (float& v : values) v *= scale;
  return values;
}

// `values` plus Gaussian noise of standard deviation `sigma` (seeded: the same on every run).
inline std::vector<float> with_noise(std::vector<float> values, float sigma, unsigned seed) {
  std::mt19937 generator(seed);
  std::normal_distribution<float> noise(0.0f, sigma);
  for (float& v : values) v += noise(generator);
  return values;
}

// An RGB image followed by its variance AOV (variance.R/G/B), interleaved per pixel.
inline void write_rgb_with_variance(const std::filesystem::path& path, int width, int height,
                                    const std::vector<float>& rgb, float variance) {
  std::vector<float> values;
  for (size_t p = 0; p < rgb.size() / 3; ++p) {
    for (int c = 0; c < 3; ++c) values.push_back(rgb[p * 3 + c]);
    for (int c = 0; c < 3; ++c) values.push_back(variance);
  }
  write_test_image(path, width, height, {"R", "G", "B", "variance.R", "variance.G", "variance.B"},
                   values);
}

}  // namespace radiant::test
