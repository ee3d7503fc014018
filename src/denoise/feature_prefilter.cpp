#include "denoise/feature_prefilter.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace radiant {

namespace {

// Feature differences at which the prefilter's weight falls to 1/e: an albedo step of 0.1, a
// normal turned by about 10 degrees, a depth step of 5% of the mean depth.
constexpr float edge_scale[denoise_feature_count] = {0.1f, 0.1f, 0.1f, 0.18f, 0.18f, 0.18f, 0.05f};

// The mean depth of the pixels that saw a surface, summed in order (the same for any thread
// count); 1 when none did.
float mean_hit_depth(const std::vector<float>& depth) {
  double sum = 0;
  size_t hits = 0;
  for (float d : depth)
    if (d > 0) sum += d, ++hits;
  return hits && sum > 0 ? float(sum / double(hits)) : 1.0f;
}

}  // namespace

DenoiseFeatures prefilter_features(const DenoiseInput& in) {
  int width = in.width, height = in.height;
  size_t count = size_t(width) * height;
  std::array<std::vector<float>, denoise_feature_count> raw;
  for (auto& plane : raw) plane.resize(count);
  float depth_scale = 1 / mean_hit_depth(in.depth);
  for (size_t i = 0; i < count; ++i) {
    for (int k = 0; k < 3; ++k) raw[k][i] = in.albedo[i][k], raw[3 + k][i] = in.normal[i][k];
    raw[6][i] = in.depth[i] * depth_scale;
  }
  DenoiseFeatures out;
  out.width = width, out.height = height;
  for (auto& plane : out.planes) plane.resize(count);
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = 0; x < width; ++x) {
        size_t i = size_t(y) * width + x;
        float sum[denoise_feature_count] = {}, weight_sum = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
            size_t j = size_t(ny) * width + nx;
            float distance = 0;
            for (int k = 0; k < denoise_feature_count; ++k) {
              float d = (raw[k][j] - raw[k][i]) / edge_scale[k];
              distance += d * d;
            }
            float w = std::exp(-distance);
            weight_sum += w;
            for (int k = 0; k < denoise_feature_count; ++k) sum[k] += w * raw[k][j];
          }
        for (int k = 0; k < denoise_feature_count; ++k) out.planes[k][i] = sum[k] / weight_sum;
      }
  });
  return out;
}

}  // namespace radiant
