// A batch's commonest path vertex shaded across SIMD lanes: a triangle of an untransformed mesh,
// a Lambert material, lit by one point light through opaque shadows. The
// batched path tracer (integrators/path.cpp) gathers such vertices of a stage into these lanes,
// shades them together and scatters the results back; every other vertex, and every lane this
// kernel cannot finish (`fallback`), is shaded one path at a time. Each lane's results are what
// the one-path code gives, to the bit: the same operations in the same order (math/lane_isa.h).
#pragma once

#include <cstdint>

#include "integrators/render_context.h"
#include "math/lane_isa.h"

namespace radiant {

struct LambertLanes {
  static constexpr int capacity = max_batch_paths;
  // Inputs: the triangle (its vertices, Embree's barycentrics and unnormalised normal, and its
  // vertex normals where `has_normals`), the ray's direction, the albedo, the chosen light (position, attenuation, intensity, the
  // probability it was chosen with), the bounce's cosine-warped local direction and the path's
  // throughput.
  alignas(32) float p0x[capacity], p0y[capacity], p0z[capacity];
  alignas(32) float p1x[capacity], p1y[capacity], p1z[capacity];
  alignas(32) float p2x[capacity], p2y[capacity], p2z[capacity];
  alignas(32) float b1[capacity], b2[capacity];
  alignas(32) float ngx[capacity], ngy[capacity], ngz[capacity];
  alignas(32) int32_t has_normals[capacity];
  alignas(32) float n0x[capacity], n0y[capacity], n0z[capacity];
  alignas(32) float n1x[capacity], n1y[capacity], n1z[capacity];
  alignas(32) float n2x[capacity], n2y[capacity], n2z[capacity];
  alignas(32) float dx[capacity], dy[capacity], dz[capacity];
  alignas(32) float albedo_r[capacity], albedo_g[capacity], albedo_b[capacity];
  alignas(32) float light_x[capacity], light_y[capacity], light_z[capacity];
  alignas(32) float kc[capacity], kl[capacity], kq[capacity];
  alignas(32) float intensity_r[capacity], intensity_g[capacity], intensity_b[capacity];
  alignas(32) float select_pdf[capacity];
  alignas(32) float cosine_x[capacity], cosine_y[capacity], cosine_z[capacity];
  alignas(32) float throughput_r[capacity], throughput_g[capacity], throughput_b[capacity];

  // Outputs. `fallback`: a value left float's normal range where the one-path code rescales it;
  // the vertex must be shaded one path at a time. Otherwise: the hit's position and the
  // shading normal facing the ray (the path's previous_*); `scatters`, and where it does the
  // next ray (origin, direction wi) and its pdf; `lit`, and where it is the shadow ray
  // (origin, direction; tmax 1 - 1e-4) and the light's contribution through the throughput.
  alignas(32) int32_t fallback[capacity], scatters[capacity], lit[capacity];
  alignas(32) float px[capacity], py[capacity], pz[capacity];
  alignas(32) float nx[capacity], ny[capacity], nz[capacity];
  alignas(32) float ox[capacity], oy[capacity], oz[capacity];
  alignas(32) float wix[capacity], wiy[capacity], wiz[capacity];
  alignas(32) float pdf[capacity];
  alignas(32) float shadow_ox[capacity], shadow_oy[capacity], shadow_oz[capacity];
  alignas(32) float shadow_dx[capacity], shadow_dy[capacity], shadow_dz[capacity];
  alignas(32) float light_r[capacity], light_g[capacity], light_b[capacity];
  int count = 0;
};

// Shades lanes [0, count).
void shade_lambert_lanes(LambertLanes& lanes, LaneIsa isa = LaneIsa::best);

}  // namespace radiant
