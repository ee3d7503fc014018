// inverse_survives_float: which instance transforms Embree can invert in single precision. Every
// refused case here aborted inside Embree (`ray.valid()`) or traced the wrong object-space ray;
// every accepted one must trace through an instance to the exact hit.
#include <doctest/doctest.h>

#include <string>

#include "accel/scene_accel.h"
#include "math/transform.h"
#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

struct Case {
  const char* name;
  mat4 transform;
};

// Rows (a b c / d e f / g h i) with no translation.
mat4 linear(float a, float b, float c, float d, float e, float f, float g, float h, float i) {
  mat4 m;
  const float rows[3][3] = {{a, b, c}, {d, e, f}, {g, h, i}};
  for (int r = 0; r < 3; ++r)
    for (int col = 0; col < 3; ++col) m.m[r][col] = rows[r][col];
  return m;
}

const float ulp = 1.0f / (1 << 23);  // 2^-23, float's spacing just above 1

}  // namespace

TEST_CASE("transform inverse: transforms whose float inverse fails are refused") {
  const Case refused[] = {
      {"zero scale", scaling({1, 0, 1})},
      {"uniform scale 1e-13 (determinant 1e-39, below float's normal range)", scaling({1e-13f, 1e-13f, 1e-13f})},
      {"uniform scale 1e-16 (determinant 0 in float)", scaling({1e-16f, 1e-16f, 1e-16f})},
      {"uniform scale 1e13 (determinant beyond float)", scaling({1e13f, 1e13f, 1e13f})},
      // Determinant -ulp² in double, 0 in float: 1 - ulp² rounds to 1.
      {"two rows equal but for one ulp", linear(1 + ulp, 1, 0, 1, 1 - ulp, 0, 0, 0, 1)},
      {"three rows nearly equal", linear(1 + ulp, 1, 1, 1, 1 - ulp, 1, 1, 1, 1 + ulp)},
  };
  for (const Case& c : refused) {
    CAPTURE(std::string(c.name));
    CHECK(!inverse_survives_float(c.transform));
  }
}

TEST_CASE("transform inverse: accepted transforms trace through an instance to the exact hit") {
  const Case accepted[] = {
      {"identity", mat4{}},
      {"uniform scale 1e-12", scaling({1e-12f, 1e-12f, 1e-12f})},
      {"uniform scale 1e12", scaling({1e12f, 1e12f, 1e12f})},
      {"a quad flattened to 1e-6 and turned", rotation_axis(normalize(vec3{1, 2, 3}), 40) * scaling({1, 1e-6f, 1})},
      {"a shear by 10", linear(1, 10, 0, 0, 1, 0, 0, 0, 1)},
      {"moved, turned and scaled", translation({5, -3, 2}) * rotation_axis({0, 1, 0}, 30) * scaling({2, 0.5f, 3})},
  };
  for (const Case& c : accepted) {
    CAPTURE(std::string(c.name));
    REQUIRE(inverse_survives_float(c.transform));
    SceneDesc scene;
    add_quad(scene, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, add_diffuse(scene, {0.5f, 0.5f, 0.5f}));
    scene.instances[0].transform = c.transform;
    scene.instances.push_back(scene.instances[0]);  // placed twice: traced in its object space
    scene.instances[1].transform = c.transform * translation({0, 0, -4});
    auto accel = build_scene_accel(scene);
    // From above the point (0.3, 0.2, 0) of the quad, straight down in object space: t = 1.
    vec3 target = transform_point(c.transform, {0.3f, 0.2f, 0});
    vec3 origin = transform_point(c.transform, {0.3f, 0.2f, 1});
    HitId hit = intersect_nearest(*accel, Ray{origin, target - origin});
    REQUIRE(hit.valid());
    CHECK(hit.t == doctest::Approx(1).epsilon(1e-4));
    CHECK(accel->untraceable_rays.load() == 0);
  }
}
