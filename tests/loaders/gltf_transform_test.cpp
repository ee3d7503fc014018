// glTF node transforms: TRS, matrix, hierarchy, shared meshes, mirroring, cycles.
#include <doctest/doctest.h>

#include "loaders/gltf_builder.h"
#include "load_scene.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

static SceneDesc load_nodes(const std::string& nodes_and_scenes) {
  ScratchDir dir("gltf-transform");
  return load_scene(dir.write("scene.gltf", quad_builder().gltf(std::string(quad_mesh) + "," + nodes_and_scenes)).string());
}

static std::string load_error(const std::string& nodes_and_scenes) {
  try {
    load_nodes(nodes_and_scenes);
  } catch (const LoadError& error) {
    return error.what();
  }
  return "no error";
}

static vec3 world_of(const SceneDesc& scene, int instance, vec3 p) {
  return transform_point(scene.instances[instance].transform, p);
}

TEST_CASE("gltf: translation, rotation and scale compose as T*R*S") {
  // Rotate 90 degrees about Z, scale x by 2, move by (10,0,0): (1,0,0) -> (2,0,0) -> (0,2,0) -> (10,2,0).
  SceneDesc scene = load_nodes(
      "\"nodes\":[{\"mesh\":0,\"translation\":[10,0,0],\"rotation\":[0,0,0.70710678,0.70710678],\"scale\":[2,1,1]}],"
      "\"scenes\":[{\"nodes\":[0]}]");
  vec3 p = world_of(scene, 0, {1, 0, 0});
  CHECK(p.x == doctest::Approx(10));
  CHECK(p.y == doctest::Approx(2));
  CHECK(p.z == doctest::Approx(0).epsilon(1e-6));
}

TEST_CASE("gltf: a column-major matrix is read as glTF writes it") {
  SceneDesc scene = load_nodes("\"nodes\":[{\"mesh\":0,\"matrix\":[1,0,0,0, 0,1,0,0, 0,0,1,0, 3,4,5,1]}],"
                               "\"scenes\":[{\"nodes\":[0]}]");
  vec3 p = world_of(scene, 0, {1, 1, 0});
  CHECK(p.x == 4);
  CHECK(p.y == 5);
  CHECK(p.z == 5);
}

TEST_CASE("gltf: child transforms compose with their parents and the mesh is stored once") {
  SceneDesc scene = load_nodes(
      "\"nodes\":[{\"translation\":[0,10,0],\"scale\":[2,2,2],\"children\":[1,2]},"
      "{\"mesh\":0,\"translation\":[1,0,0]},{\"mesh\":0,\"translation\":[0,0,1]}],\"scenes\":[{\"nodes\":[0]}]");
  CHECK(scene.meshes.size() == 1);
  REQUIRE(scene.instances.size() == 2);
  CHECK(scene.instances[1].mesh == 0);
  vec3 a = world_of(scene, 0, {0, 0, 0}), b = world_of(scene, 1, {1, 0, 0});
  CHECK(a.x == 2);
  CHECK(a.y == 10);
  CHECK(b.x == 2);
  CHECK(b.z == 2);
}

TEST_CASE("gltf: a mirroring instance gets a copy of the mesh with reversed winding") {
  SceneDesc scene = load_nodes("\"nodes\":[{\"mesh\":0},{\"mesh\":0,\"scale\":[-1,1,1]},{\"mesh\":0,\"scale\":[1,-1,1]}],"
                               "\"scenes\":[{\"nodes\":[0,1,2]}]");
  REQUIRE(scene.meshes.size() == 2);
  CHECK(scene.instances[0].mesh == 0);
  CHECK(scene.instances[1].mesh == 1);
  CHECK(scene.instances[2].mesh == 1);  // one copy serves every mirroring instance
  CHECK(scene.meshes[1].indices == std::vector<uint32_t>{0, 2, 1, 0, 3, 2});
  // The world-space winding of the copy faces +Z, like the unmirrored quad.
  const MeshDesc& copy = scene.meshes[1];
  vec3 p0 = world_of(scene, 1, copy.positions[copy.indices[0]]);
  vec3 p1 = world_of(scene, 1, copy.positions[copy.indices[1]]);
  vec3 p2 = world_of(scene, 1, copy.positions[copy.indices[2]]);
  CHECK(cross(p1 - p0, p2 - p0).z > 0);
}

TEST_CASE("gltf: scenes other than the default are chosen by index") {
  ScratchDir dir("gltf-scenes");
  std::string body = std::string(quad_mesh) +
                     ",\"nodes\":[{\"mesh\":0},{\"mesh\":0,\"translation\":[7,0,0]}],\"scene\":0,"
                     "\"scenes\":[{\"nodes\":[0]},{\"nodes\":[1]}]";
  std::string path = dir.write("s.gltf", quad_builder().gltf(body)).string();
  LoadOptions options;
  options.gltf_scene = 1;
  CHECK(load_scene(path, options).instances.at(0).transform.m[0][3] == 7);
  options.gltf_scene = 2;
  CHECK_THROWS_WITH_AS(load_scene(path, options), (path + ": scene 2 out of range (2 scenes)").c_str(), LoadError);
}

TEST_CASE("gltf: cycles and shared children in the node graph are errors, not stack overflows") {
  CHECK(load_error("\"nodes\":[{\"mesh\":0,\"children\":[1]},{\"children\":[0]}],\"scenes\":[{\"nodes\":[0]}]")
            .find("scene.gltf: nodes[1].children[0]: cycle in the node graph (node 0 is its own ancestor)") !=
        std::string::npos);
  CHECK(load_error("\"nodes\":[{\"mesh\":0,\"children\":[0]}],\"scenes\":[{\"nodes\":[0]}]")
            .find("nodes[0].children[0]: cycle in the node graph") != std::string::npos);
  CHECK(load_error("\"nodes\":[{\"children\":[2]},{\"children\":[2]},{\"mesh\":0}],\"scenes\":[{\"nodes\":[0,1]}]")
            .find("nodes[1].children[0]: node 2 is reached twice") != std::string::npos);
}

TEST_CASE("gltf: a very deep hierarchy loads without recursion") {
  std::string nodes = "\"nodes\":[";
  const int depth = 20000;
  for (int i = 0; i < depth; ++i)
    nodes += i + 1 < depth ? "{\"children\":[" + std::to_string(i + 1) + "]}," : std::string("{\"mesh\":0}");
  SceneDesc scene = load_nodes(nodes + "],\"scenes\":[{\"nodes\":[0]}]");
  CHECK(scene.instances.size() == 1);
}

TEST_CASE("gltf: non-finite and out-of-range node data name the node") {
  CHECK(load_error("\"nodes\":[{\"mesh\":0,\"translation\":[1e39,0,0]}],\"scenes\":[{\"nodes\":[0]}]")
            .find("scene.gltf: nodes[0].translation: non-finite value") != std::string::npos);
  CHECK(load_error("\"nodes\":[{\"mesh\":0,\"scale\":[1e30,1e30,1e30],\"children\":[1]},"
                   "{\"mesh\":0,\"scale\":[1e30,1e30,1e30]}],\"scenes\":[{\"nodes\":[0]}]")
            .find("scene.gltf: nodes[1]: non-finite world transform") != std::string::npos);
  CHECK(load_error("\"nodes\":[{\"mesh\":3}],\"scenes\":[{\"nodes\":[0]}]")
            .find("scene.gltf: nodes[0].mesh: mesh 3 out of range (1 meshes)") != std::string::npos);
}
