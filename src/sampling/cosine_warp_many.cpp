#include "sampling/cosine_warp.h"

namespace radiant {

namespace {

// Compiled twice and picked at load time, as the Sobol lanes are (sampler_many.cpp). Neither
// target has FMA, so no multiply-add is fused and each lane rounds as the scalar warp does.
[[gnu::target_clones("avx2", "default")]] void cosine_lanes(const float* __restrict u_x, const float* __restrict u_y,
                                                             int count, float* __restrict x, float* __restrict y,
                                                             float* __restrict z) {
  for (int i = 0; i < count; ++i) {
    vec3 d = cosine_hemisphere(u_x[i], u_y[i]);
    x[i] = d.x, y[i] = d.y, z[i] = d.z;
  }
}

}  // namespace

void cosine_hemisphere_many(const float* u_x, const float* u_y, int count, float* x, float* y, float* z) {
  cosine_lanes(u_x, u_y, count, x, y, z);
}

}  // namespace radiant
