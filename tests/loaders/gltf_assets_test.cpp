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

TEST_CASE("assets: the checker cube loads its external buffer and nearest-filtered texture") {
  SceneDesc scene = load_scene(source_path("assets/models/checker-cube.gltf").string());
  REQUIRE(scene.meshes.size() == 1);
  CHECK(scene.meshes[0].triangle_count() == 12);
  CHECK(scene.images.at(0).width == 64);
  CHECK(scene.images.at(0).channels == 3);
  CHECK(scene.textures.at(0).filter == TextureFilter::nearest);
  CHECK(scene.cameras.size() == 1);
  CHECK(scene.lights.at(0).kind == LightKind::point);
  // The camera was aimed at the origin.
  vec3 to_origin = normalize(-scene.cameras[0].position);
  CHECK(dot(to_origin, scene.cameras[0].forward) == doctest::Approx(1));
  for (const MeshDesc& mesh : scene.meshes) check_winding_matches_normals(mesh);
}

TEST_CASE("assets: the instanced GLB stores its box once and one mirrored copy") {
  SceneDesc scene = load_scene(source_path("assets/models/instanced-boxes.glb").string());
  CHECK(scene.meshes.size() == 3);  // box, ground, mirrored box
  CHECK(scene.instances.size() == 11);
  CHECK(scene.lights.at(0).kind == LightKind::directional);
  CHECK(scene.cameras.size() == 1);
}

TEST_CASE("assets: the normal-mapped quad gets generated tangents") {
  SceneDesc scene = load_scene(source_path("assets/models/normal-mapped-quad.gltf").string());
  REQUIRE(scene.meshes.size() == 1);
  CHECK(scene.meshes[0].tangents.size() == 4);
  CHECK(scene.meshes[0].tangents[0].x == doctest::Approx(1));
  CHECK(scene.materials.at(0).normal_texture.valid());
  CHECK(scene.lights.at(0).kind == LightKind::spot);
}

TEST_CASE("assets: the textured OBJ cube maps its MTL texture") {
  SceneDesc scene = load_scene(source_path("assets/models/textured-cube.obj").string());
  REQUIRE(scene.meshes.size() == 1);
  CHECK(scene.meshes[0].triangle_count() == 12);
  CHECK(scene.materials.at(0).base_color_texture.valid());
  CHECK(scene.images.at(0).width == 64);
  // The OBJ and the glTF cube carry the same texture coordinates once v is flipped.
  SceneDesc gltf = load_scene(source_path("assets/models/checker-cube.gltf").string());
  CHECK(scene.meshes[0].texcoords0[0].y == doctest::Approx(gltf.meshes[0].texcoords0[0].y));
  CHECK(scene.meshes[0].texcoords0[2].y == doctest::Approx(gltf.meshes[0].texcoords0[2].y));
}
