// Capped cylinders and infinite tubes by equivalence classes: caps, side, misses, inside, parallel.
#include <doctest/doctest.h>

#include "accel/analytic_shapes.h"

using namespace radiant;

namespace {

ShapeDesc cylinder() {  // base at the origin, axis +z, radius 1, height 2
  ShapeDesc s;
  s.kind = ShapeKind::cylinder;
  s.center = {0, 0, 0};
  s.axis = {0, 0, 1};
  s.radius = 1;
  s.height = 2;
  return s;
}

ShapeDesc tube() {  // the z axis, radius 1, infinite
  ShapeDesc s = cylinder();
  s.kind = ShapeKind::tube;
  return s;
}

void check_hit(const ShapeDesc& s, Ray ray, float t, vec3 normal) {
  ShapeHit hit;
  REQUIRE(intersect_shape(s, ray, 0, hit));
  CHECK(hit.t == doctest::Approx(t));
  CHECK(hit.normal.x == doctest::Approx(normal.x));
  CHECK(hit.normal.y == doctest::Approx(normal.y));
  CHECK(hit.normal.z == doctest::Approx(normal.z));
}

bool hits(const ShapeDesc& s, Ray ray) {
  ShapeHit hit;
  return intersect_shape(s, ray, 0, hit);
}

}  // namespace

TEST_CASE("cylinder: rays along the axis hit the top and the bottom cap with the cap normals") {
  check_hit(cylinder(), {{0.3f, 0.2f, 5}, {0, 0, -1}}, 3, {0, 0, 1});
  check_hit(cylinder(), {{0.3f, 0.2f, -5}, {0, 0, 1}}, 5, {0, 0, -1});
}

TEST_CASE("cylinder: a ray across the side hits it with the radial normal, above or beside it misses") {
  check_hit(cylinder(), {{5, 0, 1}, {-1, 0, 0}}, 4, {1, 0, 0});
  check_hit(cylinder(), {{0, -5, 0.5f}, {0, 1, 0}}, 4, {0, -1, 0});
  CHECK_FALSE(hits(cylinder(), {{5, 0, 2.5f}, {-1, 0, 0}}));  // above the top cap
  CHECK_FALSE(hits(cylinder(), {{5, 1.5f, 1}, {-1, 0, 0}}));  // beside it
  CHECK_FALSE(hits(cylinder(), {{5, 0, 1}, {1, 0, 0}}));      // pointing away
}

TEST_CASE("cylinder: from inside, rays hit the side or a cap from within, with the outward normal") {
  check_hit(cylinder(), {{0, 0, 1}, {1, 0, 0}}, 1, {1, 0, 0});
  check_hit(cylinder(), {{0, 0, 1}, {0, 0, 1}}, 1, {0, 0, 1});
}

TEST_CASE("cylinder: a ray entering through the side and leaving through a cap reports the nearer hit") {
  // From (2, 0, 1.5) towards (-1, 0, 3.5): it crosses the side at x = 1 (t = 1), before z = 2.
  Ray ray{{2, 0, 1.5f}, {-1, 0, 0.25f}};
  check_hit(cylinder(), ray, 1, {1, 0, 0});
}

TEST_CASE("tube: infinite along its axis, open: side hits at any height, axis-parallel rays never hit") {
  check_hit(tube(), {{5, 0, 100}, {-1, 0, 0}}, 4, {1, 0, 0});
  check_hit(tube(), {{5, 0, -1e4f}, {-1, 0, 0}}, 4, {1, 0, 0});
  CHECK_FALSE(hits(tube(), {{0.5f, 0, 0}, {0, 0, 1}}));  // inside, along the axis
  CHECK_FALSE(hits(tube(), {{3, 0, 0}, {0, 0, 1}}));     // outside, parallel
  check_hit(tube(), {{0, 0, 7}, {0, 1, 0}}, 1, {0, 1, 0});  // from inside: the far wall
}

TEST_CASE("sphere: a ray through the centre hits the near side, a ray passing beside it misses") {
  ShapeDesc s;
  s.kind = ShapeKind::sphere;
  s.center = {0, 0, -5};
  s.radius = 2;
  check_hit(s, {{0, 0, 0}, {0, 0, -1}}, 3, {0, 0, 1});
  CHECK_FALSE(hits(s, {{2.5f, 0, 0}, {0, 0, -1}}));
}
