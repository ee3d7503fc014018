// Which meshes sit flat on Embree's top level and which stay instanced, and that both layouts
// report the same hits (docs/performance.md: the flat BVH is the fast one).
#include <doctest/doctest.h>

#include <random>

#include "accel/scene_accel.h"
#include "math/transform.h"
#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

MeshDesc tilted_quad(int material) {
  MeshDesc mesh;
  mesh.material = material;
  mesh.positions = {{-1, -1, 0.3f}, {1, -1, -0.2f}, {1, 1, 0.1f}, {-1, 1, 0.4f}};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

// One placement of mesh 0 per transform.
SceneDesc placed(const std::vector<mat4>& transforms) {
  SceneDesc scene;
  scene.meshes.push_back(tilted_quad(add_diffuse(scene, {0.5f, 0.5f, 0.5f})));
  for (const mat4& t : transforms) {
    InstanceDesc instance;
    instance.mesh = 0;
    instance.transform = t;
    scene.instances.push_back(instance);
  }
  return scene;
}

}  // namespace

TEST_CASE("accel layout: a mesh placed once goes flat only when its world vertices are exact floats") {
  CHECK(build_scene_accel(placed({mat4{}}))->mesh_scenes[0] == nullptr);
  CHECK(build_scene_accel(placed({translation({8, -2, 0}) * scaling({2, 2, 0.25f})}))->mesh_scenes[0] == nullptr);
  // 0.3 + 1e6 is no float: rounding would bend the quad, so it stays instanced.
  CHECK(build_scene_accel(placed({translation({1e6f, 0, 0})}))->mesh_scenes[0] == nullptr);
  CHECK(build_scene_accel(placed({translation({0, 0, 1e6f})}))->mesh_scenes[0] != nullptr);
  CHECK(build_scene_accel(placed({rotation_axis({0, 1, 0}, 30)}))->mesh_scenes[0] != nullptr);
  // Placed twice: shared by two instances.
  CHECK(build_scene_accel(placed({mat4{}, translation({4, 0, 0})}))->mesh_scenes[0] != nullptr);
}

TEST_CASE("accel layout: flat and instanced placements of the same quad report the same hits") {
  const mat4 shift = translation({2, 1, 0});  // keeps the vertices exact floats
  SceneDesc flat = placed({shift});
  auto flat_accel = build_scene_accel(flat);
  REQUIRE(flat_accel->mesh_scenes[0] == nullptr);
  // The same placement twice over, the second far away: the first is now an instance.
  SceneDesc instanced = placed({shift, translation({100, 0, 0})});
  auto instanced_accel = build_scene_accel(instanced);
  REQUIRE(instanced_accel->mesh_scenes[0] != nullptr);

  std::mt19937 rng(3);
  std::uniform_real_distribution<float> across(-1.2f, 1.2f);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    vec3 target = vec3{2, 1, 0} + vec3{across(rng), across(rng), 0.2f};
    Ray ray = {target + vec3{across(rng), across(rng), 5}, vec3{0, 0, -5}};
    HitId a = intersect_nearest(*flat_accel, ray), b = intersect_nearest(*instanced_accel, ray);
    REQUIRE(a.valid() == b.valid());
    if (!a.valid()) continue;
    ++hits;
    CHECK(a.instance == 0);
    CHECK(b.instance == 0);
    CHECK(a.primitive == b.primitive);
    CHECK(a.t == doctest::Approx(b.t).epsilon(1e-5));
    SurfaceHit ha = make_surface_hit(*flat_accel, ray, a), hb = make_surface_hit(*instanced_accel, ray, b);
    CHECK(length(ha.position - hb.position) < 1e-5f);
    CHECK(dot(ha.geometric_normal, hb.geometric_normal) > 0.99999f);
    CHECK(is_occluded(*flat_accel, ray));
  }
  CHECK(hits > 500);  // most rays are aimed inside the quad
}

TEST_CASE("accel layout: an untransformed triangle's geometric normal points out of its counter-clockwise side") {
  // Untransformed hits take Embree's own Ng; it must be the unit cross product of the edges
  // from either side, flat on the top level (placed once) or instanced (placed twice).
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> coordinate(-3, 3);
  for (int placements : {1, 2}) {
    for (int trial = 0; trial < 200; ++trial) {
      SceneDesc scene;
      MeshDesc mesh;
      mesh.material = add_diffuse(scene, {0.5f, 0.5f, 0.5f});
      for (int v = 0; v < 3; ++v) mesh.positions.push_back({coordinate(rng), coordinate(rng), coordinate(rng)});
      mesh.indices = {0, 1, 2};
      scene.meshes.push_back(mesh);
      for (int p = 0; p < placements; ++p) {
        InstanceDesc instance;
        instance.mesh = 0;
        instance.transform = p == 0 ? mat4{} : translation({50, 0, 0});
        scene.instances.push_back(instance);
      }
      auto accel = build_scene_accel(scene);
      REQUIRE((accel->mesh_scenes[0] == nullptr) == (placements == 1));
      vec3 e1 = mesh.positions[1] - mesh.positions[0], e2 = mesh.positions[2] - mesh.positions[0];
      vec3 expected = normalize(cross(e1, e2));
      if (length(cross(e1, e2)) < 1e-3f) continue;  // nearly degenerate: no clear side
      vec3 centroid = (mesh.positions[0] + mesh.positions[1] + mesh.positions[2]) * (1.0f / 3);
      for (float side : {1.0f, -1.0f}) {
        Ray ray = {centroid + expected * (10 * side), expected * -side};
        HitId id = intersect_nearest(*accel, ray);
        REQUIRE(id.valid());
        SurfaceHit hit = make_surface_hit(*accel, ray, id);
        CHECK(dot(hit.geometric_normal, expected) > 0.99999f);
        CHECK(hit.front_face == (side > 0));
      }
    }
  }
}
