// validate_scene: indices in range, finite numbers, something to render.
#include <doctest/doctest.h>

#include <cmath>

#include "load_scene.h"
#include "scene/validate.h"

using namespace radiant;

static SceneDesc triangle_scene() {
  SceneDesc scene;
  scene.source_path = "s.gltf";
  scene.materials.push_back({});
  MeshDesc mesh;
  mesh.material = 0;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.indices = {0, 1, 2};
  scene.meshes.push_back(mesh);
  scene.instances.push_back({0, mat4{}, "tri"});
  return scene;
}

static std::string problem(const SceneDesc& scene) {
  try {
    validate_scene(scene);
  } catch (const LoadError& error) {
    return error.what();
  }
  return "valid";
}

TEST_CASE("validate: a well-formed scene passes") { CHECK(problem(triangle_scene()) == "valid"); }

TEST_CASE("validate: indices out of range name the element") {
  SceneDesc scene = triangle_scene();
  scene.meshes[0].indices = {0, 1, 2, 0, 2, 7};
  CHECK(problem(scene) == "s.gltf: meshes[0].indices[5]: index 7 out of range (3 vertices)");
  scene = triangle_scene();
  scene.instances[0].mesh = 2;
  CHECK(problem(scene) == "s.gltf: instances[0].mesh: mesh 2 out of range (1 meshes)");
  scene = triangle_scene();
  scene.materials[0].normal_texture.texture = 0;
  CHECK(problem(scene) == "s.gltf: materials[0].normal_texture.texture: texture 0 out of range (0 textures)");
  scene = triangle_scene();
  scene.textures.push_back({3});
  CHECK(problem(scene) == "s.gltf: textures[0].image: image 3 out of range (0 images)");
  scene = triangle_scene();
  scene.meshes[0].normals = {{0, 0, 1}};
  CHECK(problem(scene) == "s.gltf: meshes[0].normals: 1 values for 3 vertices");
}

TEST_CASE("validate: non-finite numbers and degenerate directions are refused") {
  SceneDesc scene = triangle_scene();
  scene.meshes[0].positions[1].y = NAN;
  CHECK(problem(scene) == "s.gltf: meshes[0].positions[1]: non-finite value");
  scene = triangle_scene();
  scene.meshes[0].normals = {{0, 0, 1}, {0, 0, 0}, {0, 0, 1}};
  CHECK(problem(scene) == "s.gltf: meshes[0].normals[1]: zero-length direction");
  scene = triangle_scene();
  scene.instances[0].transform.m[0][3] = INFINITY;
  CHECK(problem(scene) == "s.gltf: instances[0].transform: non-finite value");
  scene = triangle_scene();
  scene.lights.push_back({});
  scene.lights[0].intensity.x = INFINITY;
  CHECK(problem(scene) == "s.gltf: lights[0].intensity: non-finite value");
  scene = triangle_scene();
  scene.cameras.push_back({});
  scene.cameras[0].forward = {0, 0, 0};
  CHECK(problem(scene) == "s.gltf: cameras[0].forward: zero-length direction");
  scene = triangle_scene();
  scene.shapes.push_back({ShapeKind::sphere, 0, {0, 0, 0}, {0, 0, 1}, 0});
  CHECK(problem(scene) == "s.gltf: shapes[0].radius: must be positive");
  scene = triangle_scene();
  scene.shapes.push_back({ShapeKind::plane, 0, {0, 0, 0}, {0, 0, 0}, 1});
  CHECK(problem(scene) == "s.gltf: shapes[0].axis: zero-length direction");
}

TEST_CASE("validate: a scene with nothing placed has nothing to render") {
  SceneDesc scene = triangle_scene();
  scene.instances.clear();
  CHECK(problem(scene) == "s.gltf: scene: nothing to render (no meshes placed, no shapes, no lines or points)");
}

TEST_CASE("validate: a singular instance transform names the file and the instance") {
  // Caught at validation, before the accelerator is built, with the file's name.
  SceneDesc scene = triangle_scene();
  scene.instances[0].transform.m[1][1] = 0;
  CHECK(problem(scene) == "s.gltf: instances[0].transform: singular transform");
}

TEST_CASE("validate: an instance transform too close to singular for float is refused by name") {
  // Embree inverts it in single precision; it aborted on the rays that inverse made.
  SceneDesc scene = triangle_scene();
  scene.instances[0].transform = scaling({1e-16f, 1e-16f, 1e-16f});
  CHECK(problem(scene) ==
        "s.gltf: instances[0].transform: too close to singular to invert in single precision, as ray tracing must");
}

TEST_CASE("validate: negative radiance, reflectance and light intensity are refused") {
  SceneDesc scene = triangle_scene();
  scene.materials[0].emission = {1, -1, 1};
  CHECK(problem(scene) == "s.gltf: materials[0].emission: negative value");
  scene = triangle_scene();
  scene.materials[0].kd = {-0.5f, 0, 0};
  CHECK(problem(scene) == "s.gltf: materials[0].kd: negative value");
  scene = triangle_scene();
  scene.lights.push_back({});
  scene.lights[0].intensity = {0, 0, -1};
  CHECK(problem(scene) == "s.gltf: lights[0].intensity: negative value");
  scene = triangle_scene();
  scene.environment.color = {-1, 0, 0};
  CHECK(problem(scene) == "s.gltf: environment.color: negative value");
}
