// False-color difference images.
#include "image/false_color.h"

#include <algorithm>
#include <cmath>

#include "image/image_format.h"
#include "image/image_io.h"

namespace radiant {

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

}  // namespace

void write_false_color(TemporaryFile& file, const std::vector<float>& magnitude, int width, int height,
                       float top) {
  ImageWriteSpec spec;
  spec.width = width;
  spec.height = height;
  spec.channel_names = {"R", "G", "B"};
  spec.type = image_format_of(file.target()).named_channels ? PixelType::half : PixelType::uint8;
  write_image_file(file, spec, colorize(magnitude, top).data());
}

}  // namespace radiant
