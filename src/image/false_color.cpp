// False-color difference images, written atomically.
#include "image/false_color.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "image/compare.h"
#include "image/image_io.h"
#include "image/image_writer.h"

namespace radiant {

namespace fs = std::filesystem;

color3 false_color(float t) {
  if (std::isnan(t)) t = 1;
  t = std::clamp(t, 0.0f, 1.0f) * 3;
  // Red rises over the first third, then green, then blue: black, red, yellow, white.
  return {std::min(t, 1.0f), std::clamp(t - 1, 0.0f, 1.0f), std::clamp(t - 2, 0.0f, 1.0f)};
}

namespace {

std::vector<float> colorize(const std::vector<float>& magnitude, float top) {
  std::vector<float> rgb(magnitude.size() * 3);
  for (size_t p = 0; p < magnitude.size(); ++p) {
    color3 color = false_color(top > 0 ? magnitude[p] / top : (magnitude[p] > 0 ? 1.0f : 0.0f));
    for (int c = 0; c < 3; ++c) rgb[p * 3 + c] = color[c];
  }
  return rgb;
}

// Writes `rgb` to `file` in the format `path`'s extension names (half float for EXR, else
// 8 bits); returns an error message or "".
std::string write_rgb(const fs::path& file, const std::string& path, const std::vector<float>& rgb, int width,
                      int height) {
  ImageWriteSpec spec;
  spec.width = width;
  spec.height = height;
  spec.channel_names = {"R", "G", "B"};
  spec.type = lowercase_extension(path) == ".exr" ? PixelType::half : PixelType::uint8;
  return write_image_file(file.string(), spec, rgb.data());
}

}  // namespace

void write_false_color(const std::string& path, const std::vector<float>& magnitude, int width,
                       int height, float top) {
  fs::path target(path), temporary = temporary_path_beside(path);
  std::string error = write_rgb(temporary, path, colorize(magnitude, top), width, height);
  std::error_code ignored;
  if (error.empty()) {
    std::error_code renamed;
    fs::rename(temporary, target, renamed);
    if (renamed) error = renamed.message();
  }
  if (!error.empty()) {
    fs::remove(temporary, ignored);
    throw CompareError(path + ": cannot write difference image: " + error);
  }
}

}  // namespace radiant
