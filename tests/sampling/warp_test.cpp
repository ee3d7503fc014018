// Warps: the cosine-weighted hemisphere against the concentric mapping worked out in double
// precision with libm's sine and cosine, and the same warp run across many samples in SIMD.
#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "sampling/cosine_warp.h"
#include "sampling/warp.h"

using namespace radiant;

namespace {

// Shirley-Chiu as written in their paper, in double precision.
void concentric_reference(vec2 u, double& x, double& y) {
  double a = 2.0 * u.x - 1, b = 2.0 * u.y - 1, r, phi;
  if (a == 0 && b == 0) {
    x = y = 0;
    return;
  }
  if (std::abs(a) > std::abs(b)) {
    r = a;
    phi = (M_PI / 4) * (b / a);
  } else {
    r = b;
    phi = (M_PI / 2) - (M_PI / 4) * (a / b);
  }
  x = r * std::cos(phi);
  y = r * std::sin(phi);
}

}  // namespace

TEST_CASE("warp: the cosine-weighted hemisphere is the concentric mapping to float precision") {
  // A 257x257 grid hits every wedge, both diagonals (where the major axis switches) and the edges.
  double worst = 0;
  for (int i = 0; i <= 256; ++i) {
    for (int j = 0; j <= 256; ++j) {
      vec2 u = {float(i) / 256, float(j) / 256};
      vec3 d = sample_cosine_hemisphere(u);
      double x, y;
      concentric_reference(u, x, y);
      worst = std::max({worst, std::abs(d.x - x), std::abs(d.y - y)});
      REQUIRE(d.z >= 0);
      REQUIRE(std::abs(double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z - 1) < 1e-6);
    }
  }
  CHECK(worst < 4e-7);
}

TEST_CASE("warp: the centre of the square maps to the normal") {
  vec3 d = sample_cosine_hemisphere({0.5f, 0.5f});
  CHECK(d.x == 0);
  CHECK(d.y == 0);
  CHECK(d.z == 1);
}

TEST_CASE("warp: cosine-weighted directions warped many at once are the scalar warp's to the bit") {
  // The centre (the pole), the corners and edges of the square, the diagonals (where the major
  // axis changes), and random points.
  std::vector<float> ux = {0.5f, 0, 0, 0x1.fffffep-1f, 0.25f, 0.75f, 0.5f, 0.5f, 0.3f};
  std::vector<float> uy = {0.5f, 0, 0x1.fffffep-1f, 0.5f, 0.25f, 0.25f, 0.1f, 0x1.fffffep-1f, 0.7f};
  uint32_t state = 7;
  auto next = [&] { return float((state = state * 1664525u + 1013904223u) >> 8) * 0x1p-24f; };
  while (ux.size() < 1003) ux.push_back(next()), uy.push_back(next());
  for (LaneIsa isa : {LaneIsa::best, LaneIsa::baseline, LaneIsa::avx2}) {
    if (!lane_isa_available(isa)) continue;
    CAPTURE(int(isa));
    std::vector<float> x(ux.size()), y(ux.size()), z(ux.size());
    cosine_hemisphere_many(ux.data(), uy.data(), int(ux.size()), x.data(), y.data(), z.data(), isa);
    for (size_t i = 0; i < ux.size(); ++i) {
      CAPTURE(ux[i]);
      CAPTURE(uy[i]);
      vec3 d = sample_cosine_hemisphere({ux[i], uy[i]});
      REQUIRE(std::bit_cast<uint32_t>(x[i]) == std::bit_cast<uint32_t>(d.x));
      REQUIRE(std::bit_cast<uint32_t>(y[i]) == std::bit_cast<uint32_t>(d.y));
      REQUIRE(std::bit_cast<uint32_t>(z[i]) == std::bit_cast<uint32_t>(d.z));
    }
    CHECK(x[0] == 0);
    CHECK(y[0] == 0);
    CHECK(z[0] == 1);
  }
}
