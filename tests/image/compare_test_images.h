// Small images written with OpenImageIO for the comparison tests.
#pragma once

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace radiant::test {

// Writes `values` (width*height*names.size(), row-major) with those channel names; EXR as float.
inline void write_test_image(const std::filesystem::path& path, int width, int height,
                             const std::vector<std::string>& names,
                             const std::vector<float>& values) {
  auto output = OIIO::ImageOutput::create(path.string());
  if (!output) throw std::runtime_error("no writer for " + path.string());
  bool is_exr = path.extension() == ".exr";
  OIIO::ImageSpec spec(width, height, int(names.size()),
                       is_exr ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  spec.channelnames = names;
  spec.alpha_channel = -1;
  for (size_t c = 0; c < names.size(); ++c)
    if (names[c] == "A") spec.alpha_channel = int(c);
  if (!output->open(path.string(), spec) ||
      !output->write_image(OIIO::TypeDesc::FLOAT, values.data()) || !output->close())
    throw std::runtime_error("cannot write " + path.string() + ": " + output->geterror());
}

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
