// normalize() gives a unit vector at every scale float holds: a huge triangle's cross product,
// whose squared length overflows, and a tiny one's, whose squared length underflows. In float's
// normal range it is bit for bit the plain a / |a| it always was.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "math/vec.h"

using namespace radiant;

namespace {

bool same_bits(vec3 a, vec3 b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("normalize: unit length for vectors whose squared length overflows or underflows") {
  for (vec3 v : {vec3{3e19f, -4e19f, 0}, vec3{1e38f, 1e38f, 1e38f}, vec3{3e-25f, 0, -4e-25f}, vec3{0, 1e-45f, 0},
                 vec3{-2e-40f, 2e-40f, 1e-40f}}) {
    vec3 n = normalize(v);
    CAPTURE(v.x);
    CAPTURE(v.y);
    CAPTURE(v.z);
    CHECK(std::abs(length(n) - 1) < 1e-6f);
    CHECK(dot(n, v) > 0);  // the same direction
  }
  CHECK(normalize(vec3{3e19f, -4e19f, 0}).x == doctest::Approx(0.6f));
}

TEST_CASE("normalize: the plain formula in float's normal range, zero, infinities and NaN unchanged") {
  for (vec3 v : {vec3{1, 2, 3}, vec3{-1e18f, 5, 2e17f}, vec3{1e-18f, 0, 0}}) CHECK(same_bits(normalize(v), v * (1 / length(v))));
  CHECK(same_bits(normalize(vec3{0, 0, 0}), vec3{0, 0, 0}));
  float inf = std::numeric_limits<float>::infinity();
  CHECK(std::isinf(normalize(vec3{inf, 0, 0}).x));
  CHECK(std::isnan(normalize(vec3{std::nanf(""), 1, 0}).x));
}
