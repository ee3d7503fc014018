// How much of a surface one pixel sees, for choosing a texture's mip level: pbrt-v4's
// camera-derived approximation (CameraBase::Approximate_dp_dxy), used at every path vertex.
// It needs no ray differentials carried along paths and no random numbers, so the sampler's
// dimensions and the image's independence of tiles, shards and threads stay as they were.
#pragma once

#include <cmath>
#include <cstdint>

#include "math/vec.h"

namespace radiant {

// The smallest change between neighbouring pixels' camera rays over the image (render space):
// how far their origins move and how far their unit directions turn, per pixel in x and in y.
struct PixelSpread {
  vec3 camera_position;
  vec3 forward = {0, 0, -1}, right = {1, 0, 0}, up = {0, 1, 0};
  bool parallel = false;  // orthographic: every camera ray runs along `forward`
  float origin_step_x = 0, origin_step_y = 0;
  float direction_step_x = 0, direction_step_y = 0;
};

// The change of surface point `p` (geometric normal `n`) across one pixel in x and in y: where
// rays one pixel's spread away from the camera ray through p meet p's tangent plane.
void approximate_dp_dxy(const PixelSpread& spread, vec3 p, vec3 n, vec3& dpdx, vec3& dpdy);

// The share of that footprint that sample `index` of a pixel filters textures over: all of it
// for the first sample, then 1/sqrt(index + 1), down to an eighth. Filtering every sample over a
// whole pixel blurs the texture a second time on top of the pixel's own integral, an error that
// more samples cannot remove; pbrt-v4 narrows the footprint by 1/sqrt(spp) for that reason. Going
// by the sample's own index instead, a sample's value does not depend on the render's spp, so
// sample ranges, shards and renders extended by more samples add up exactly.
inline float texture_footprint_scale(uint32_t index) {
  float scale = 1.0f / std::sqrt(float(index) + 1.0f);
  return scale > 0.125f ? scale : 0.125f;
}

}  // namespace radiant
