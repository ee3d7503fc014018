#include "denoise/denoise_channels.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace radiant {

namespace {

int channel_index(const std::vector<std::string>& channels, const std::string& name) {
  auto found = std::find(channels.begin(), channels.end(), name);
  return found == channels.end() ? -1 : int(found - channels.begin());
}

}  // namespace

const std::vector<std::string>& denoise_channel_names() {
  static const std::vector<std::string> names = {"R",   "G",   "B",   "albedo.R", "albedo.G", "albedo.B",
                                                 "N.X", "N.Y", "N.Z", "Z",        "even.R",   "even.G",
                                                 "even.B", "odd.R", "odd.G", "odd.B"};
  return names;
}

DenoiseInput denoise_input_from_channels(int width, int height, const std::vector<std::string>& channels,
                                         const std::vector<float>& pixels, const std::string& path) {
  const std::vector<std::string>& names = denoise_channel_names();
  std::vector<int> index;
  for (const std::string& name : names) {
    index.push_back(channel_index(channels, name));
    if (index.back() < 0)
      throw std::runtime_error(path + ": no channel '" + name +
                               "' (the denoiser needs colour, albedo, normal, depth and the half images: render to "
                               "EXR with --aov albedo,normal,depth,halves)");
  }
  int variance[3] = {channel_index(channels, "variance.R"), channel_index(channels, "variance.G"),
                     channel_index(channels, "variance.B")};
  bool has_variance = variance[0] >= 0 && variance[1] >= 0 && variance[2] >= 0;
  size_t stride = channels.size(), count = size_t(width) * height;
  DenoiseInput in;
  in.width = width, in.height = height;
  in.color.resize(count), in.even.resize(count), in.odd.resize(count), in.variance.resize(count);
  in.albedo.resize(count), in.normal.resize(count), in.depth.resize(count);
  for (size_t i = 0; i < count; ++i) {
    const float* p = &pixels[i * stride];
    for (size_t k = 0; k < names.size(); ++k)
      if (!std::isfinite(p[index[k]]))
        throw std::runtime_error(path + ": pixel (" + std::to_string(i % width) + ", " + std::to_string(i / width) +
                                 ") channel '" + names[k] + "' is not finite");
    for (int c = 0; c < 3; ++c) {
      in.color[i][c] = p[index[c]];
      in.albedo[i][c] = p[index[3 + c]];
      in.normal[i][c] = p[index[6 + c]];
      in.even[i][c] = p[index[10 + c]];
      in.odd[i][c] = p[index[13 + c]];
      // Without the film's variance, the halves' difference estimates it: (even - odd)^2 / 4 is
      // unbiased for the variance of their mean.
      float d = in.even[i][c] - in.odd[i][c];
      in.variance[i][c] = has_variance ? std::max(0.0f, p[variance[c]]) : d * d / 4;
    }
    in.depth[i] = p[index[9]];
  }
  return in;
}

void set_image_color(OutputImage& image, const std::vector<color3>& color) {
  size_t stride = image.channels.size();
  int r = channel_index(image.channels, "R"), g = channel_index(image.channels, "G"), b = channel_index(image.channels, "B");
  for (size_t i = 0; i < color.size(); ++i) {
    float* p = &image.pixels[i * stride];
    p[r] = color[i].x, p[g] = color[i].y, p[b] = color[i].z;
  }
}

}  // namespace radiant
