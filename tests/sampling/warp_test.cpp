// Warps: the cosine-weighted hemisphere against the concentric mapping worked out in double
// precision with libm's sine and cosine.
#include <doctest/doctest.h>

#include <cmath>

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
