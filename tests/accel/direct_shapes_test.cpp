// Tracing a few shapes directly (accel/direct_shapes.h) finds what Embree finds: the same shape,
// t, uv and normal for every ray, and the same answer for every shadow ray. The float test that
// skips spheres a ray surely misses must never skip one the exact test hits; rays that graze a
// sphere within a part in a million of its radius probe that margin.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "accel/direct_shapes.h"
#include "accel/scene_accel.h"
#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

SceneDesc few_shapes() {
  SceneDesc scene;
  int m = add_diffuse(scene, {0.5f, 0.5f, 0.5f});
  add_sphere(scene, {0, 1, 0}, 1, m);
  add_sphere(scene, {2.5f, 0.5f, 1}, 0.5f, m);
  add_sphere(scene, {-2, 0.3f, 2}, 1e-3f, m);    // tiny
  add_sphere(scene, {0, -1000, 0}, 999.5f, m);  // huge, its top just below the plane
  add_sphere(scene, {1, 1, -2}, 1, m);          // overlaps the first
  add_plane(scene, {0, 0, 0}, {0, 1, 0}, m);
  add_plane(scene, {0, 0, -6}, {0, 0, 1}, m);
  ShapeDesc cylinder;
  cylinder.kind = ShapeKind::cylinder;
  cylinder.material = m;
  cylinder.center = {-2, 0, -1};
  cylinder.axis = {0, 1, 0};
  cylinder.radius = 0.4f;
  cylinder.height = 2;
  scene.shapes.push_back(cylinder);
  ShapeDesc tube = cylinder;
  tube.kind = ShapeKind::tube;
  tube.center = {3, 0, -3};
  tube.axis = normalize(vec3{1, 1, 0});
  scene.shapes.push_back(tube);
  return scene;
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Rays from a box around the shapes in every direction, some with a finite tmax, and rays that
// graze each sphere: their line passes within (1 ± 1e-6) of its radius from the centre.
std::vector<Ray> probe_rays(const SceneDesc& scene, int count) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> across(-5, 5), unit(-1, 1), fraction(0, 1);
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    vec3 d = normalize(vec3{unit(rng), unit(rng), unit(rng)});
    float tmax = i % 3 == 0 ? 10 * fraction(rng) : std::numeric_limits<float>::infinity();
    rays.push_back({{across(rng), across(rng) + 5, across(rng)}, d * (0.5f + fraction(rng)), tmax});
  }
  for (const ShapeDesc& s : scene.shapes) {
    if (s.kind != ShapeKind::sphere) continue;
    for (int i = 0; i < count / 10; ++i) {
      vec3 d = normalize(vec3{unit(rng), unit(rng), unit(rng)});
      vec3 side = normalize(cross(d, vec3{unit(rng), unit(rng), unit(rng)}));
      float offset = s.radius * (1 + 1e-6f * unit(rng));
      float back = (1 + 3 * fraction(rng)) * s.radius;
      rays.push_back({s.center + side * offset - d * back, d});
    }
  }
  return rays;
}

}  // namespace

TEST_CASE("direct shapes: a few shapes and no meshes are traced directly, and find exactly Embree's hits") {
  SceneDesc scene = few_shapes();
  auto accel = build_scene_accel(scene);
  REQUIRE(accel->direct_shapes.enabled);
  int hits = 0, grazing_hits = 0, blocked = 0, compared = 0;
  std::vector<Ray> rays = probe_rays(scene, 20000);
  for (size_t r = 0; r < rays.size(); ++r) {
    const Ray& ray = rays[r];
    accel->direct_shapes.enabled = false;
    HitId embree = intersect_nearest(*accel, ray);
    bool embree_blocked = is_occluded(*accel, ray);
    accel->direct_shapes.enabled = true;
    HitId direct = intersect_nearest(*accel, ray);
    bool direct_blocked = is_occluded(*accel, ray);
    CAPTURE(r);
    REQUIRE(direct.valid() == embree.valid());
    CHECK(direct_blocked == embree_blocked);
    ++compared;
    blocked += direct_blocked;
    if (!direct.valid()) continue;
    ++hits;
    grazing_hits += r >= 20000;
    CHECK(same_bits(direct.t, embree.t));
    if (direct.shape != embree.shape) continue;  // two shapes at exactly the same t: either is right
    CHECK(direct.instance == -1);
    CHECK(direct.primitive == embree.primitive);
    CHECK((same_bits(direct.barycentric.x, embree.barycentric.x) && same_bits(direct.barycentric.y, embree.barycentric.y)));
    vec3 a = direct.geometric_normal_raw, b = embree.geometric_normal_raw;
    CHECK((same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z)));
  }
  // The probes reach every case: hits, misses, grazing hits and blocked shadow rays.
  CHECK(hits > compared / 4);
  CHECK(hits < compared);
  CHECK(grazing_hits > 100);
  CHECK(blocked > compared / 4);
}

TEST_CASE("direct shapes: meshes, or more shapes than the limit, stay with Embree") {
  SceneDesc scene = few_shapes();
  add_quad(scene, {-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}, 0);
  CHECK(!build_scene_accel(scene)->direct_shapes.enabled);
  scene = few_shapes();
  while (scene.shapes.size() <= max_shapes_traced_directly) add_sphere(scene, {0, 3, 0}, 0.1f, 0);
  CHECK(!build_scene_accel(scene)->direct_shapes.enabled);
  scene.shapes.pop_back();
  CHECK(build_scene_accel(scene)->direct_shapes.enabled);
}
