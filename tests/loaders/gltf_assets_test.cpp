// The glTF and OBJ files shipped in assets/ load, with the content their README promises.
#include <doctest/doctest.h>

#include "load_scene.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

static const MeshDesc& mesh_named(const SceneDesc& scene, const std::string& name) {
  for (const MeshDesc& mesh : scene.meshes)
    if (mesh.name == name) return mesh;
  FAIL("no mesh " << name);
  return scene.meshes[0];
}

// Every triangle's winding agrees with its vertex normals (so front faces are where normals point).
static void check_winding_matches_normals(const MeshDesc& mesh) {
  for (size_t t = 0; t < mesh.indices.size(); t += 3) {
    vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]],
         c = mesh.positions[mesh.indices[t + 2]];
    CHECK(dot(cross(b - a, c - a), mesh.normals[mesh.indices[t]]) > 0);
  }
}

TEST_CASE("assets: the Cornell box has the measured layout, camera and light") {
  SceneDesc scene = load_scene(source_path("assets/cornell.gltf").string());
  CHECK(scene.meshes.size() == 8);
  CHECK(scene.instances.size() == 8);
  REQUIRE(scene.cameras.size() == 1);
  const CameraDesc& camera = scene.cameras[0];
  CHECK(camera.position.x == doctest::Approx(0.278));
  CHECK(camera.position.z == doctest::Approx(-0.8));
  CHECK(camera.forward.z == doctest::Approx(1));
  CHECK(camera.up.y == doctest::Approx(1));
  CHECK(camera.vertical_fov_degrees == doctest::Approx(39.3).epsilon(0.01));
  CHECK(mesh_named(scene, "floor").normals[0].y == doctest::Approx(1));
  CHECK(mesh_named(scene, "ceiling").normals[0].y == doctest::Approx(-1));
  CHECK(mesh_named(scene, "back wall").normals[0].z == doctest::Approx(-1));
  CHECK(mesh_named(scene, "red wall").normals[0].x < -0.99f);  // red on the left (+x), facing in
  CHECK(mesh_named(scene, "green wall").normals[0].x == doctest::Approx(1));
  const MeshDesc& light = mesh_named(scene, "light");
  CHECK(light.normals[0].y == doctest::Approx(-1));
  const MaterialDesc& emitter = scene.materials[light.material];
  CHECK(emitter.emission.x == doctest::Approx(17));
  CHECK(emitter.emission.y == doctest::Approx(12));
  CHECK(emitter.emission.z == doctest::Approx(4));
  CHECK(scene.materials[mesh_named(scene, "red wall").material].base_color.x == doctest::Approx(0.63));
  for (const MeshDesc& mesh : scene.meshes) check_winding_matches_normals(mesh);
  CHECK(scene.warnings.empty());
}
