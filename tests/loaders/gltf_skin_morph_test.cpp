// Morph targets and skins: the posed mesh each node shows, checked against hand-computed vertices.
#include <doctest/doctest.h>

#include <cstdint>

#include "load_scene.h"
#include "loaders/gltf_builder.h"
#include "support/load_errors.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// The mesh instance `i` shows, with its positions moved to world space.
std::vector<vec3> world_positions(const SceneDesc& scene, size_t i) {
  const InstanceDesc& instance = scene.instances.at(i);
  std::vector<vec3> out;
  for (vec3 p : scene.meshes.at(size_t(instance.mesh)).positions) out.push_back(transform_point(instance.transform, p));
  return out;
}

void check_near(vec3 a, vec3 b) {
  CAPTURE(a.x);
  CAPTURE(a.y);
  CAPTURE(a.z);
  CHECK(length(a - b) < 1e-6f);
}

}  // namespace

TEST_CASE("gltf morph targets: positions move by weight x delta, node weights over mesh weights") {
  GltfBuilder b;
  b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);      // 0: POSITION
  b.floats({0, 0, 2, 0, 0, 2, 0, 0, 2}, "VEC3", 3);      // 1: target 0, +2 in z
  b.floats({4, 0, 0, 0, 0, 0, 0, 0, 0}, "VEC3", 3);      // 2: target 1, +4 in x on vertex 0
  std::string gltf = b.gltf(
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"targets\":[{\"POSITION\":1},{\"POSITION\":2}]}],"
      "\"weights\":[0.5,0]}],"
      "\"nodes\":[{\"mesh\":0},{\"mesh\":0,\"weights\":[0.25,0.5]}],\"scenes\":[{\"nodes\":[0,1]}],\"scene\":0");
  ScratchDir dir("gltf-morph");
  SceneDesc scene = load_scene(dir.write("morph.gltf", gltf).string());
  REQUIRE(scene.instances.size() == 2);
  // Node 0: the mesh's weights, 0.5 of target 0: z = 1 exactly.
  std::vector<vec3> mesh_weights = world_positions(scene, 0);
  REQUIRE(mesh_weights.size() == 3);
  CHECK(mesh_weights[0] == vec3{0, 0, 1});
  CHECK(mesh_weights[1] == vec3{1, 0, 1});
  CHECK(mesh_weights[2] == vec3{0, 1, 1});
  // Node 1: its own weights, 0.25 and 0.5: z = 0.5, and vertex 0 moves 2 in x.
  std::vector<vec3> node_weights = world_positions(scene, 1);
  REQUIRE(node_weights.size() == 3);
  CHECK(node_weights[0] == vec3{2, 0, 0.5f});
  CHECK(node_weights[1] == vec3{1, 0, 0.5f});
  CHECK(scene.instances[0].mesh != scene.instances[1].mesh);
}

TEST_CASE("gltf skins: a two-bone skin poses its vertices as hand-computed, ignoring the mesh node's transform") {
  // Joint 0 at the origin, joint 1 its child at x = 1 turned 90 degrees about z; bound at x = 1
  // unturned (inverse bind: translate -1 in x). A on joint 0, B on joint 1, C half on each.
  GltfBuilder b;
  b.floats({0, 0, 0, 2, 0, 0, 1, 1, 1}, "VEC3", 3);  // 0: POSITION A, B, C
  std::vector<uint8_t> joints = {0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0};
  b.accessor(b.view(GltfBuilder::bytes_of(joints)), 5121, 3, "VEC4");  // 1: JOINTS_0
  b.floats({1, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0}, "VEC4", 4);    // 2: WEIGHTS_0
  b.floats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,            // 3: inverse binds (column-major)
            1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 1},
           "MAT4", 16);
  std::string gltf = b.gltf(
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"JOINTS_0\":1,\"WEIGHTS_0\":2}}]}],"
      "\"skins\":[{\"joints\":[1,2],\"inverseBindMatrices\":3}],"
      "\"nodes\":[{\"mesh\":0,\"skin\":0,\"translation\":[5,0,0]},{\"children\":[2]},"
      "{\"translation\":[1,0,0],\"rotation\":[0,0,0.70710678,0.70710678]}],"
      "\"scenes\":[{\"nodes\":[0,1]}],\"scene\":0");
  ScratchDir dir("gltf-skin");
  SceneDesc scene = load_scene(dir.write("skin.gltf", gltf).string());
  REQUIRE(scene.instances.size() == 1);
  CHECK(is_identity(scene.instances[0].transform));
  std::vector<vec3> posed = world_positions(scene, 0);
  REQUIRE(posed.size() == 3);
  check_near(posed[0], {0, 0, 0});      // joint 0 does not move
  check_near(posed[1], {1, 1, 0});      // (2,0,0): bound 1 along the bone, turned to +y
  check_near(posed[2], {0.5f, 0.5f, 1});  // half (1,1,1), half its turned image (0,0,1)
}

TEST_CASE("gltf skins: joints out of range or outside the scene are errors naming them") {
  GltfBuilder b;
  b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
  std::vector<uint8_t> joints = {0, 0, 0, 0, 3, 0, 0, 0, 0, 0, 0, 0};
  b.accessor(b.view(GltfBuilder::bytes_of(joints)), 5121, 3, "VEC4");
  b.floats({1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, "VEC4", 4);
  const std::string mesh = "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"JOINTS_0\":1,\"WEIGHTS_0\":2}}]}],";
  ScratchDir dir("gltf-skin-errors");
  dir.write("range.gltf", b.gltf(mesh + "\"skins\":[{\"joints\":[1]}],\"nodes\":[{\"mesh\":0,\"skin\":0},{}],"
                                        "\"scenes\":[{\"nodes\":[0,1]}],\"scene\":0"));
  CHECK(load_error(dir, dir.file("range.gltf")) ==
        "range.gltf: meshes[0].primitives[0].attributes.JOINTS_0: joint 3 of element 1 out of range (1 joints)");
  dir.write("outside.gltf", b.gltf(mesh + "\"skins\":[{\"joints\":[1]}],\"nodes\":[{\"mesh\":0,\"skin\":0},{}],"
                                          "\"scenes\":[{\"nodes\":[0]}],\"scene\":0"));
  CHECK(load_error(dir, dir.file("outside.gltf")) == "outside.gltf: skins[0].joints[0]: node 1 is not in the rendered scene");
}

TEST_CASE("gltf skins: an instanced skinned node places its posed mesh once per instance, with a warning") {
  // One joint at the origin (no bind offset): the posed mesh is the mesh itself, in world space.
  GltfBuilder b;
  b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);  // 0: POSITION
  std::vector<uint8_t> joints = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  b.accessor(b.view(GltfBuilder::bytes_of(joints)), 5121, 3, "VEC4");  // 1: JOINTS_0
  b.floats({1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, "VEC4", 4);          // 2: WEIGHTS_0
  b.floats({0, 0, 0, 0, 0, 5}, "VEC3", 3);                             // 3: TRANSLATION
  std::string gltf = b.gltf(
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"JOINTS_0\":1,\"WEIGHTS_0\":2}}]}],"
      "\"skins\":[{\"joints\":[1]}],\"extensionsUsed\":[\"EXT_mesh_gpu_instancing\"],"
      "\"nodes\":[{\"mesh\":0,\"skin\":0,\"extensions\":{\"EXT_mesh_gpu_instancing\":{\"attributes\":"
      "{\"TRANSLATION\":3}}}},{}],\"scenes\":[{\"nodes\":[0,1]}],\"scene\":0");
  ScratchDir dir("gltf-skin-instancing");
  SceneDesc scene = load_scene(dir.write("skin.gltf", gltf).string());
  REQUIRE(scene.instances.size() == 2);
  check_near(world_positions(scene, 0)[1], {1, 0, 0});
  check_near(world_positions(scene, 1)[1], {1, 0, 5});
  REQUIRE(scene.warnings.size() == 1);
  CHECK(scene.warnings[0].find("nodes[0].extensions.EXT_mesh_gpu_instancing: instancing a skinned mesh") !=
        std::string::npos);
}
