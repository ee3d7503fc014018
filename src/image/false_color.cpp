// False-color difference images, written atomically.
#include "image/false_color.h"

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "image/compare.h"

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

// Writes `rgb` to `path` with OIIO; returns an error message or "".
std::string write_rgb(const fs::path& path, const std::string& format_of,
                      const std::vector<float>& rgb, int width, int height) {
  auto output = OIIO::ImageOutput::create(format_of);
  if (!output) return "no image format for this extension";
  bool linear_float = std::string(output->format_name()) == "openexr";
  OIIO::ImageSpec spec(width, height, 3, linear_float ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::UINT8);
  if (!output->open(path.string(), spec) ||
      !output->write_image(OIIO::TypeDesc::FLOAT, rgb.data()) || !output->close()) {
    std::string message = output->geterror();
    return message.empty() ? "write failed" : message.substr(0, message.find('\n'));
  }
  return "";
}

}  // namespace

void write_false_color(const std::string& path, const std::vector<float>& magnitude, int width,
                       int height, float top) {
  fs::path target(path);
  // Same folder and extension, so the rename is atomic and OIIO picks the format by extension.
  std::string name = ".";
  name += target.stem().string();
  name += ".tmp-" + std::to_string(getpid());
  name += target.extension().string();
  fs::path temporary = target.parent_path() / name;
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
