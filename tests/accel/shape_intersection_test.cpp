// Analytic shapes under hard rays: tangent, lying in or parallel to a plane, from inside, and
// spheres 1e-6 and 1e6 in radius; directly (intersect_shape) and through intersect_nearest, both with
// Embree and with the few shapes traced directly.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "accel/analytic_shapes.h"
#include "accel/scene_accel.h"
#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

ShapeDesc sphere(vec3 center, float radius) {
  ShapeDesc s;
  s.kind = ShapeKind::sphere;
  s.center = center;
  s.radius = radius;
  return s;
}

ShapeDesc plane(vec3 point, vec3 normal) {
  ShapeDesc s;
  s.kind = ShapeKind::plane;
  s.center = point;
  s.axis = normalize(normal);
  return s;
}

// One float step above or below 1 (the radius of the unit sphere).
const float just_above_one = std::nextafter(1.0f, 2.0f);
const float just_below_one = std::nextafter(1.0f, 0.0f);

}  // namespace

TEST_CASE("shapes: a ray tangent to a sphere touches it once at the tangent point, one float step off misses or hits") {
  for (vec3 center : {vec3{0, 0, 0}, vec3{1e6f, -1e6f, 1e6f}}) {
    CAPTURE(center.x);
    ShapeDesc s = sphere(center, 1);
    ShapeHit hit;
    // Exactly tangent: a double discriminant of zero; either a hit at the tangent point or none.
    if (intersect_shape(s, {center + vec3{-5, 1, 0}, {1, 0, 0}}, 0, hit)) {
      CHECK(hit.t == doctest::Approx(5).epsilon(1e-3));
      CHECK(hit.normal.y == doctest::Approx(1).epsilon(1e-3));
    }
    // One float step (1/16 at 1e6) above the tangent line misses, one below hits: computed
    // relative to the centre in double, the answer is as sharp as the input allows.
    float tangent_height = center.y + 1;
    float above = std::nextafter(tangent_height, std::numeric_limits<float>::infinity());
    float below = std::nextafter(tangent_height, -std::numeric_limits<float>::infinity());
    CHECK_FALSE(intersect_shape(s, {{center.x - 5, above, center.z}, {1, 0, 0}}, 0, hit));
    REQUIRE(intersect_shape(s, {{center.x - 5, below, center.z}, {1, 0, 0}}, 0, hit));
    CHECK(hit.t == doctest::Approx(5).epsilon(0.1));
    CHECK(hit.t < 5);  // the entry point, before the tangent point
    CHECK(is_finite(hit.normal));
    CHECK(length(hit.normal) == doctest::Approx(1).epsilon(1e-6));
  }
}

TEST_CASE("shapes: a ray lying in a plane or parallel to it never hits, and a nearly parallel ray hits far away") {
  ShapeHit hit;
  ShapeDesc ground = plane({0, 0, 0}, {0, 1, 0});
  CHECK_FALSE(intersect_shape(ground, {{0, 0, 0}, {1, 0, 0}}, 0, hit));
  CHECK_FALSE(intersect_shape(ground, {{3, 0, -2}, {0.6f, 0, 0.8f}}, 0, hit));
  CHECK_FALSE(intersect_shape(ground, {{0, 1, 0}, {1, 0, 0}}, 0, hit));
  CHECK_FALSE(intersect_shape(ground, {{0, -1, 0}, {0, 0, 1}}, 0, hit));
  // A tilted plane and a ray along it (the two equal normal components cancel exactly).
  ShapeDesc tilted = plane({1e5f, 1e5f, 0}, {1, 1, 0});
  CHECK_FALSE(intersect_shape(tilted, {{1e5f, 1e5f, 0}, {1, -1, 0}}, 0, hit));
  // 1e-7 radians below the horizon from height 1: t = 1e7.
  REQUIRE(intersect_shape(ground, {{0, 1, 0}, {1, -1e-7f, 0}}, 0, hit));
  CHECK(hit.t == doctest::Approx(1e7).epsilon(1e-6));
  CHECK(hit.normal == vec3{0, 1, 0});
}

TEST_CASE("shapes: rays from inside a sphere hit its far side with the outward normal") {
  ShapeHit hit;
  ShapeDesc s = sphere({2, 3, 4}, 2);
  // From the centre every direction hits at exactly the radius.
  for (vec3 d : {vec3{1, 0, 0}, vec3{0, -1, 0}, normalize(vec3{1, 2, 3})}) {
    REQUIRE(intersect_shape(s, {s.center, d}, 0, hit));
    CHECK(hit.t == doctest::Approx(2).epsilon(1e-6));
    for (int i = 0; i < 3; ++i) CHECK(hit.normal[i] == doctest::Approx(d[i]).epsilon(1e-6));
  }
  // Off centre: (2,3,4) + (1.5,0,0) going +x hits at x = 4 (t = 0.5); going -x at x = 0 (t = 3.5).
  vec3 inside = s.center + vec3{1.5f, 0, 0};
  REQUIRE(intersect_shape(s, {inside, {1, 0, 0}}, 0, hit));
  CHECK(hit.t == doctest::Approx(0.5).epsilon(1e-6));
  REQUIRE(intersect_shape(s, {inside, {-1, 0, 0}}, 0, hit));
  CHECK(hit.t == doctest::Approx(3.5).epsilon(1e-6));
  CHECK(hit.normal.x == doctest::Approx(-1).epsilon(1e-6));
  // From a point on the sphere straight into it (tmin past the start): the opposite point.
  REQUIRE(intersect_shape(s, {s.center + vec3{0, 2, 0}, {0, -1, 0}}, 1e-3f, hit));
  CHECK(hit.t == doctest::Approx(4).epsilon(1e-6));
}

TEST_CASE("shapes: a sphere of radius 1e-6 seen from 10 units is hit where it should be, with an accurate normal") {
  ShapeHit hit;
  // At the origin, where the float spacing (~1e-13 near 1e-6) resolves a fraction of the radius;
  // near 0.5 the spacing is 6e-8 and the ray itself could not be aimed within 1% of it.
  vec3 center = {0, 0, 0};
  float r = 1e-6f;
  ShapeDesc s = sphere(center, r);
  vec3 origin = center + vec3{0, 0, 10};
  REQUIRE(intersect_shape(s, {origin, {0, 0, -1}}, 0, hit));
  CHECK(hit.normal.z == doctest::Approx(1).epsilon(1e-6));
  // Aimed half a radius off centre: the normal is computed in double relative to the centre.
  vec3 aim = center + vec3{0, 0.5f * r, 0};
  REQUIRE(intersect_shape(s, {origin, aim - origin}, 0, hit));
  CHECK(hit.normal.y == doctest::Approx(0.5).epsilon(1e-3));
  CHECK(hit.normal.z == doctest::Approx(std::sqrt(0.75)).epsilon(1e-3));
  // Two radii off centre misses.
  vec3 miss = center + vec3{0, 2 * r, 0};
  CHECK_FALSE(intersect_shape(s, {origin, miss - origin}, 0, hit));
}

TEST_CASE("shapes: a sphere of radius 1e6 behaves like the ground near its top, at normal and grazing incidence") {
  ShapeHit hit;
  ShapeDesc s = sphere({0, -1e6f, 0}, 1e6f);  // top at y = 0
  REQUIRE(intersect_shape(s, {{0, 1, 0}, {0, -1, 0}}, 0, hit));
  CHECK(hit.t == doctest::Approx(1).epsilon(1e-6));
  CHECK(hit.normal.y == doctest::Approx(1).epsilon(1e-7));
  // 1/10 slope from (-10, 1): the flat-ground answer x = 0 moves by the sagitta x^2 / 2R ~ 1e-12.
  vec3 d = normalize(vec3{10, -1, 0});
  REQUIRE(intersect_shape(s, {{-10, 1, 0}, d}, 0, hit));
  CHECK(hit.t == doctest::Approx(std::sqrt(101.0)).epsilon(1e-6));
  // Skimming 1e-3 above the top misses the whole sphere (it curves away).
  CHECK_FALSE(intersect_shape(s, {{-10, 1e-3f, 0}, {1, 0, 0}}, 0, hit));
}

TEST_CASE("shapes: through Embree and traced directly, tangent, in-plane and inside rays give the same answers as intersect_shape") {
  SceneDesc scene;
  int m = add_diffuse(scene, {0.5f, 0.5f, 0.5f});
  add_sphere(scene, {1e5f, 0, 0}, 1, m);
  add_plane(scene, {0, -2, 0}, {0, 1, 0}, m);
  add_sphere(scene, {0, 0, 0}, 1e-6f, m);
  auto accel = build_scene_accel(scene);
  // A scene this small is traced directly (accel/direct_shapes.h); Embree's callbacks must agree.
  for (bool direct : {false, true}) {
    CAPTURE(direct);
    accel->direct_shapes.enabled = direct;
    // Lying in the plane y = -2 (the spheres are far above it): no hit at all.
    CHECK_FALSE(intersect_nearest(*accel, {{0, -2, 5}, {1, 0, 0}}).valid());
    // Tangent one step outside the sphere at 1e5 misses; one step inside hits it.
    CHECK_FALSE(intersect_nearest(*accel, {{1e5f - 5, just_above_one, 0}, {1, 0, 0}}).valid());
    HitId tangent = intersect_nearest(*accel, {{1e5f - 5, just_below_one, 0}, {1, 0, 0}});
    REQUIRE(tangent.valid());
    CHECK(tangent.shape == 0);
    CHECK(tangent.t == doctest::Approx(5).epsilon(1e-3));
    // From inside the sphere at 1e5 along -y: its far side at t = 1, before the plane.
    HitId inside = intersect_nearest(*accel, {{1e5f, 0, 0}, {0, -1, 0}});
    REQUIRE(inside.valid());
    CHECK(inside.shape == 0);
    CHECK(inside.t == doctest::Approx(1).epsilon(1e-6));
    // The tiny sphere is found by Embree's traversal despite its 2e-6 bounding box, and by the cull.
    HitId tiny = intersect_nearest(*accel, {{0, 0, 10}, {0, 0, -1}});
    REQUIRE(tiny.valid());
    CHECK(tiny.shape == 2);
    SurfaceHit surface = make_surface_hit(*accel, {{0, 0, 10}, {0, 0, -1}}, tiny);
    CHECK(surface.position.z == doctest::Approx(1e-6).epsilon(1e-3));
    CHECK(surface.geometric_normal.z == doctest::Approx(1).epsilon(1e-6));
  }
}
