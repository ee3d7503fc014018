// An animation's next frame updates the accelerator of the frame before (render/prepare_frame.h):
// what scene_changes reports, and that the updated accelerator finds exactly the hits of one
// built anew for the changed scene.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

#include "accel/scene_accel.h"
#include "math/transform.h"
#include "scene/scene_changes.h"
#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

MeshDesc grid_mesh(int material, int n, float height) {
  MeshDesc mesh;
  mesh.material = material;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      mesh.positions.push_back({-2 + 4.0f * i / n, -2 + 4.0f * j / n, height * float((i * 7 + j * 3) % 5) / 4});  // exact floats for the heights below
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n) + 1, d = c + 1;
      mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, c});
    }
  return mesh;
}

void place(SceneDesc& scene, int mesh, const mat4& transform) {
  InstanceDesc instance;
  instance.mesh = mesh;
  instance.transform = transform;
  scene.instances.push_back(instance);
}

// A floor that never moves, a block that turns and deforms, a cloth that deforms on the top level, a shared mesh placed twice,
// one mesh placed flat that will turn and one turned that will come to rest, and a sphere.
SceneDesc frame_scene(float time) {
  SceneDesc scene;
  int material = add_diffuse(scene, {0.5f, 0.5f, 0.5f});
  scene.meshes.push_back(grid_mesh(material, 24, 0.125f));           // 0: floor
  scene.meshes.push_back(grid_mesh(material, 3, 0.5f * (1 + time)));  // 1: block, turning and growing
  scene.meshes.push_back(grid_mesh(material, 8, 0.0f));              // 2: cloth
  scene.meshes.push_back(grid_mesh(material, 2, 0.25f));             // 3: shared
  scene.meshes.push_back(grid_mesh(material, 2, 0.25f));             // 4: comes to turn
  scene.meshes.push_back(grid_mesh(material, 2, 0.5f));              // 5: comes to rest
  for (size_t v = 0; v < scene.meshes[2].positions.size(); ++v)  // in 64ths: it stays flat while it waves
    scene.meshes[2].positions[v].z = std::round(20 * std::sin(float(v) + 3 * time)) / 64;
  place(scene, 0, translation({0, 0, -1}));
  place(scene, 1, translation({0.5f, 0, 0}) * rotation_axis({0, 0, 1}, 10 + 40 * time) * scaling({0.2f, 0.2f, 0.2f}));
  place(scene, 2, translation({0, 0, 0.5f}) * scaling({0.5f, 0.5f, 0.5f}));
  place(scene, 3, translation({-1, 1, 0}) * scaling({0.25f, 0.25f, 0.25f}));
  place(scene, 3, translation({1, -1, 0}) * rotation_axis({1, 0, 0}, 20 * time) * scaling({0.25f, 0.25f, 0.25f}));
  mat4 small = scaling({0.25f, 0.25f, 0.25f});
  place(scene, 4, translation({-1, -1, 0.25f}) * (time == 0 ? mat4{} : rotation_axis({0, 1, 0}, 30)) * small);
  place(scene, 5, translation({1, 1, 0.25f}) * (time == 0 ? rotation_axis({0, 1, 0}, 30) : mat4{}) * small);
  add_sphere(scene, {1.5f + 0.2f * time, 0, 0}, 0.3f, material);
  return scene;
}

bool is_instanced(const SceneAccel& accel, int instance) {
  return std::find(accel.instanced.begin(), accel.instanced.end(), instance) != accel.instanced.end();
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("scene changes: moved instances, deformed meshes and shapes, none when the scene is built differently") {
  SceneDesc before = frame_scene(0), after = frame_scene(1);
  std::optional<SceneChanges> changes = scene_changes(before, after);
  REQUIRE(changes);
  CHECK(changes->moved_instances == std::vector<char>{0, 1, 0, 0, 1, 1, 1});
  CHECK(changes->deformed_meshes == std::vector<char>{0, 1, 1, 0, 0, 0});
  CHECK(changes->shapes_changed);
  CHECK(changes->any());
  CHECK_FALSE(scene_changes(before, frame_scene(0))->any());

  SceneDesc other_triangles = after;
  std::swap(other_triangles.meshes[1].indices[0], other_triangles.meshes[1].indices[1]);
  CHECK_FALSE(scene_changes(before, other_triangles));
  SceneDesc other_mesh = after;
  other_mesh.instances[1].mesh = 2;
  CHECK_FALSE(scene_changes(before, other_mesh));
  SceneDesc masked = after;
  masked.materials[0].alpha_mode = AlphaMode::mask;
  CHECK_FALSE(scene_changes(before, masked));
  SceneDesc fewer = after;
  fewer.shapes.clear();
  CHECK_FALSE(scene_changes(before, fewer));
}

TEST_CASE("accel update: the next frame's updated two-level accelerator finds exactly the hits of a new build") {
  SceneDesc scene = frame_scene(0);
  auto updated = build_scene_accel(scene, AccelLayout::two_level);
  CHECK_FALSE(is_instanced(*updated, 0));  // the floor and the cloth lie flat
  CHECK(is_instanced(*updated, 1));
  CHECK_FALSE(is_instanced(*updated, 2));
  CHECK_FALSE(is_instanced(*updated, 5));  // still, then turned
  CHECK(is_instanced(*updated, 6));        // turned, then still
  SceneDesc next = frame_scene(1);
  std::optional<SceneChanges> changes = scene_changes(scene, next);
  REQUIRE(changes);
  scene = next;  // in place: the accelerator points to it
  update_scene_accel(*updated, *changes);

  SceneDesc fresh_scene = frame_scene(1);
  auto fresh = build_scene_accel(fresh_scene);
  CHECK(updated->instanced == fresh->instanced);  // laid out as a new build lays it out
  CHECK(is_instanced(*updated, 5));
  CHECK_FALSE(is_instanced(*updated, 6));
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> across(-2.5f, 2.5f);
  int hits = 0, instances_hit = 0, shapes_hit = 0;
  for (int i = 0; i < 20000; ++i) {
    Ray ray = {{across(rng), across(rng), 4}, normalize(vec3{across(rng) * 0.3f, across(rng) * 0.3f, -1})};
    HitId a = intersect_nearest(*updated, ray), b = intersect_nearest(*fresh, ray);
    REQUIRE(a.valid() == b.valid());
    REQUIRE(is_occluded(*updated, ray) == is_occluded(*fresh, ray));
    if (!a.valid()) continue;
    ++hits;
    instances_hit += a.instance > 0;
    shapes_hit += a.shape >= 0;
    REQUIRE(a.instance == b.instance);
    REQUIRE(a.shape == b.shape);
    REQUIRE(a.primitive == b.primitive);
    REQUIRE(same_bits(a.t, b.t));
    REQUIRE(same_bits(a.barycentric.x, b.barycentric.x));
    REQUIRE(same_bits(a.barycentric.y, b.barycentric.y));
  }
  CHECK(hits > 5000);
  CHECK(instances_hit > 1000);  // the moving and deforming things are seen, not only the floor
  CHECK(shapes_hit > 100);
}
