// The features the denoiser's regression fits colour against: albedo, normal and depth, brought
// to comparable scales and prefiltered, so that their own noise (textures and edges under few
// samples) does not pass into the fit.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "denoise/denoise_input.h"

namespace radiant {

constexpr int denoise_feature_count = 7;  // albedo r, g, b; normal x, y, z; depth

// One plane per feature, one value per pixel.
struct DenoiseFeatures {
  int width = 0, height = 0;
  std::array<std::vector<float>, denoise_feature_count> planes;
};

// Albedo and normal as they are, depth over the image's mean depth of what the camera hit, each
// smoothed over 3x3 pixels by weights that fall off with the difference of all features (a
// cross-bilateral filter): noise goes, edges between surfaces stay. Runs on the calling task
// arena's threads; the same result for any thread count.
DenoiseFeatures prefilter_features(const DenoiseInput& in);

constexpr uint64_t denoise_features_pixel_bytes = denoise_feature_count * sizeof(float);

}  // namespace radiant
