#include "sampling/cosine_warp.h"

namespace radiant {

namespace {

// The scalar warp across the lanes, compiled for AVX2 and the SSE2 baseline (math/lane_isa.h).
[[gnu::always_inline]] inline void cosine_lanes(const float* __restrict u_x, const float* __restrict u_y, int count,
                                                float* __restrict x, float* __restrict y, float* __restrict z) {
  for (int i = 0; i < count; ++i) {
    vec3 d = cosine_hemisphere(u_x[i], u_y[i]);
    x[i] = d.x, y[i] = d.y, z[i] = d.z;
  }
}

[[gnu::target("avx2")]] void cosine_lanes_avx2(const float* u_x, const float* u_y, int count, float* x, float* y,
                                                float* z) {
  cosine_lanes(u_x, u_y, count, x, y, z);
}
void cosine_lanes_baseline(const float* u_x, const float* u_y, int count, float* x, float* y, float* z) {
  cosine_lanes(u_x, u_y, count, x, y, z);
}

}  // namespace

void cosine_hemisphere_many(const float* u_x, const float* u_y, int count, float* x, float* y, float* z,
                            LaneIsa isa) {
  if (resolve_lane_isa(isa) == LaneIsa::avx2)
    cosine_lanes_avx2(u_x, u_y, count, x, y, z);
  else
    cosine_lanes_baseline(u_x, u_y, count, x, y, z);
}

}  // namespace radiant
