// The .scene loader: the older format, the syntax shared by every block, and the assets.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <streambuf>

#include "loaders/scene_format_test_support.h"
#include "support/test_support.h"

using namespace radiant;
using doctest::Approx;

static void check_vec3(vec3 actual, vec3 expected) {
  CHECK(actual.x == Approx(expected.x));
  CHECK(actual.y == Approx(expected.y));
  CHECK(actual.z == Approx(expected.z));
}

// ---------------------------------------------------------------- the older format

static const char* older_scene = R"(scene my old room
@viewer
p 0 1 5
f 0 0 -3
@wall
n 0 2 0
p 0 -1 0
c 255 0 51
@wall
n 0 0 1
p 0 0 -10
c 51 102 204
e 2
s false
@sphere
r 0.5
p 1 2 3
e 10
)";

TEST_CASE("older format: scene name and viewer with the default fov and up") {
  SceneDesc scene = test::load_scene_text(older_scene);
  CHECK(scene.name == "my old room");
  REQUIRE(scene.cameras.size() == 1);
  const CameraDesc& camera = scene.cameras[0];
  CHECK(camera.name == "viewer");
  CHECK(camera.projection == Projection::perspective);
  check_vec3(camera.position, {0, 1, 5});
  check_vec3(camera.forward, {0, 0, -1});
  check_vec3(camera.up, {0, 1, 0});
  CHECK(camera.vertical_fov_degrees == 60);
  CHECK(camera.aspect == 0);
}

TEST_CASE("older format: smooth wall is diffuse with kd = c/255") {
  SceneDesc scene = test::load_scene_text(older_scene);
  REQUIRE(scene.shapes.size() == 3);
  const ShapeDesc& wall = scene.shapes[0];
  CHECK(wall.kind == ShapeKind::plane);
  check_vec3(wall.center, {0, -1, 0});
  check_vec3(wall.axis, {0, 1, 0});
  const MaterialDesc& material = scene.materials.at(size_t(wall.material));
  CHECK(material.model == MaterialModel::phong);
  check_vec3(material.kd, {1, 0, 0.2f});
  check_vec3(material.ka, {1, 0, 0.2f});
  check_vec3(material.kr, {0, 0, 0});
  check_vec3(material.emission, {0, 0, 0});
  CHECK(material.ior == 1);
}

TEST_CASE("older format: a wall that is not smooth is a mirror, and e scales c into emission") {
  SceneDesc scene = test::load_scene_text(older_scene);
  const MaterialDesc& material = scene.materials.at(size_t(scene.shapes[1].material));
  check_vec3(scene.shapes[1].axis, {0, 0, 1});
  check_vec3(material.kd, {0, 0, 0});
  check_vec3(material.ka, {0, 0, 0});
  check_vec3(material.kr, {0.2f, 0.4f, 0.8f});
  check_vec3(material.emission, {0.4f, 0.8f, 1.6f});
}

TEST_CASE("older format: s takes true and false in any case, as the older reader did") {
  for (const char* word : {"True", "FALSE", "tRuE", "false"}) {
    SceneDesc scene = test::load_scene_text(std::string("@sphere\nr 1\np 0 0 0\ns ") + word + "\n");
    bool smooth = std::string(word).size() == 4;  // "true" in some case
    const MaterialDesc& material = scene.materials.at(size_t(scene.shapes[0].material));
    CHECK_MESSAGE((material.kd.x > 0) == smooth, word);  // smooth: diffuse; not: a mirror
    CHECK_MESSAGE((material.kr.x > 0) == !smooth, word);
  }
}

TEST_CASE("older format: a sphere takes the defaults c = 255 255 255 and s = true") {
  SceneDesc scene = test::load_scene_text(older_scene);
  const ShapeDesc& sphere = scene.shapes[2];
  CHECK(sphere.kind == ShapeKind::sphere);
  CHECK(sphere.radius == 0.5f);
  check_vec3(sphere.center, {1, 2, 3});
  const MaterialDesc& material = scene.materials.at(size_t(sphere.material));
  check_vec3(material.kd, {1, 1, 1});
  check_vec3(material.kr, {0, 0, 0});
  check_vec3(material.emission, {10, 10, 10});
  CHECK(scene.lights.empty());
}

TEST_CASE("older format: a viewer facing straight down or up falls back to up = (0, 0, sign(f.y))") {
  SceneDesc down = test::load_scene_text("@viewer\np 0 10 0\nf 0 -2 0\n");
  check_vec3(down.cameras[0].forward, {0, -1, 0});
  check_vec3(down.cameras[0].up, {0, 0, -1});
  SceneDesc up = test::load_scene_text("@viewer\np 0 0 0\nf 0 1 0\n");
  check_vec3(up.cameras[0].up, {0, 0, 1});
}

TEST_CASE("older format: a tilted viewer gets an up orthogonal to its facing") {
  SceneDesc scene = test::load_scene_text("@viewer\np 0 0 0\nf 0 -1 -1\n");
  const CameraDesc& camera = scene.cameras[0];
  check_vec3(camera.forward, {0, -0.70710678f, -0.70710678f});
  check_vec3(camera.up, {0, 0.70710678f, -0.70710678f});
}

TEST_CASE("the scene line is optional, and its name may be absent") {
  CHECK(test::load_scene_text("@sphere\nr 1\np 0 0 0\n").name.empty());
  CHECK(test::load_scene_text("scene\n@sphere\nr 1\np 0 0 0\n").name.empty());
  CHECK(test::load_scene_text("# a comment first\n\nscene   two  words  \n").name == "two words");
}

// ---------------------------------------------------------------- syntax

TEST_CASE("comments, blank lines, tabs, CRLF and free whitespace are ignored") {
  SceneDesc scene = test::load_scene_text(
      "# header comment\r\n\r\n   @sphere   # the ball\r\n\tr\t2 # radius\r\n p 1  2\t3#no space before\r\n\n");
  REQUIRE(scene.shapes.size() == 1);
  CHECK(scene.shapes[0].radius == 2);
  check_vec3(scene.shapes[0].center, {1, 2, 3});
}

TEST_CASE("attributes may come in any order") {
  SceneDesc a = test::load_scene_text("@wall\nn 0 0 1\np 1 2 3\nc 10 20 30\ne 1\ns false\n");
  SceneDesc b = test::load_scene_text("@wall\ns false\ne 1\nc 10 20 30\np 1 2 3\nn 0 0 1\n");
  check_vec3(a.shapes[0].center, b.shapes[0].center);
  check_vec3(a.shapes[0].axis, b.shapes[0].axis);
  check_vec3(a.materials[0].kr, b.materials[0].kr);
  check_vec3(a.materials[0].emission, b.materials[0].emission);
}

TEST_CASE("numbers may have exponents, signs, and no leading or trailing digits") {
  SceneDesc scene = test::load_scene_text("@sphere\np 1e-5 -0.5 +3\nr .5\n@sphere\np 5. -2E2 +1e+1\nr 1\n");
  CHECK(scene.shapes[0].center.x == 1e-5f);
  CHECK(scene.shapes[0].center.y == -0.5f);
  CHECK(scene.shapes[0].center.z == 3.0f);
  CHECK(scene.shapes[0].radius == 0.5f);
  check_vec3(scene.shapes[1].center, {5, -200, 10});
}

// A stream that hands out one character at a time and cannot seek, like a pipe on stdin.
struct TrickleBuffer : std::streambuf {
  std::string text;
  size_t next = 0;
  char current = 0;
  explicit TrickleBuffer(std::string t) : text(std::move(t)) {}
  int_type underflow() override {
    if (gptr() && gptr() < egptr()) return traits_type::to_int_type(*gptr());
    if (next == text.size()) return traits_type::eof();
    current = text[next++];
    setg(&current, &current, &current + 1);
    return traits_type::to_int_type(current);
  }
};

TEST_CASE("the loader reads any istream, such as a non-seekable pipe") {
  TrickleBuffer buffer("scene piped\n@sphere\nr 3\np 0 0 -1");  // no final newline
  std::istream in(&buffer);
  SceneDesc scene = load_scene_format(in, "<stdin>", ".", {});
  CHECK(scene.name == "piped");
  REQUIRE(scene.shapes.size() == 1);
  CHECK(scene.shapes[0].radius == 3);
}

TEST_CASE("an empty file gives an empty scene") {
  SceneDesc scene = test::load_scene_text("");
  CHECK(scene.shapes.empty());
  CHECK(scene.cameras.empty());
  CHECK(scene.materials.empty());
}

// ---------------------------------------------------------------- assets

static SceneDesc load_asset(const std::string& name) {
  std::filesystem::path path = test::source_path("assets/" + name);
  std::ifstream in(path, std::ios::binary);
  REQUIRE(in);
  return load_scene_format(in, path.string(), path.parent_path().string(), {});
}

TEST_CASE("asset first-render.scene: the classic first render, converted") {
  SceneDesc scene = load_asset("first-render.scene");
  REQUIRE(scene.cameras.size() == 1);
  const CameraDesc& camera = scene.cameras[0];
  check_vec3(camera.position, {0, 0, 1000});
  check_vec3(camera.forward, {0, 0, -1});
  CHECK(camera.vertical_fov_degrees == Approx(11.421186));  // 2 atan(100 / 1000)
  CHECK(camera.aspect == 1);
  CHECK(camera.width == 800);
  CHECK(camera.height == 800);
  REQUIRE(scene.lights.size() == 1);
  const LightDesc& light = scene.lights[0];
  CHECK(light.kind == LightKind::spot);
  check_vec3(light.intensity, {pi * 400 / 255, pi * 240 / 255, 0});
  check_vec3(light.position, {60, 50, 0});
  check_vec3(light.direction, normalize({-1, -1, -2}));
  CHECK(light.kc == 1);
  CHECK(light.kl == 1e-5f);
  CHECK(light.kq == 5e-6f);
  CHECK(light.spot_exponent == 1);
  CHECK_FALSE(light.use_cone);
  REQUIRE(scene.shapes.size() == 1);
  CHECK(scene.shapes[0].radius == 50);
  check_vec3(scene.shapes[0].center, {0, 0, -200});
  const MaterialDesc& material = scene.materials.at(size_t(scene.shapes[0].material));
  check_vec3(material.emission, {100.0f / 255, 50.0f / 255, 50.0f / 255});
  check_vec3(material.kd, {0.5f, 0.5f, 0.5f});
  check_vec3(material.ks, {0.5f, 0.5f, 0.5f});
  check_vec3(material.kr, {0.3f, 0.3f, 0.3f});
  CHECK(material.shininess == 100);
  CHECK(scene.settings.mode == RenderMode::whitted);
  CHECK(scene.settings.sampler == SamplerKind::jittered);
  CHECK(scene.settings.spp == 81);
  CHECK(scene.settings.width == 800);
  CHECK(scene.settings.height == 800);
}

TEST_CASE("asset showcase.scene: ten or more bodies of four or more kinds, four kinds of light") {
  SceneDesc scene = load_asset("showcase.scene");
  size_t faces = 0;
  for (const MeshDesc& mesh : scene.meshes) faces += mesh.triangle_count();
  int spheres = 0, planes = 0, cylinders = 0, tubes = 0;
  for (const ShapeDesc& shape : scene.shapes) {
    spheres += shape.kind == ShapeKind::sphere;
    planes += shape.kind == ShapeKind::plane;
    cylinders += shape.kind == ShapeKind::cylinder;
    tubes += shape.kind == ShapeKind::tube;
  }
  CHECK(spheres == 5);
  CHECK(planes == 2);
  CHECK(cylinders == 1);
  CHECK(tubes == 1);
  CHECK(faces == 2 + 3 + 4);  // two triangles, a pentagon, a hexagon
  bool kinds[4] = {};
  for (const LightDesc& light : scene.lights) kinds[int(light.kind)] = true;
  CHECK((kinds[0] && kinds[1] && kinds[2] && kinds[3]));
  int transparent = 0;
  for (const MeshDesc& mesh : scene.meshes)
    transparent += !is_black(scene.materials.at(size_t(mesh.material)).kt);
  CHECK(transparent == 2);
}

TEST_CASE("asset depth-of-field.scene: a six-bladed lens focused on the middle of five balls") {
  SceneDesc scene = load_asset("depth-of-field.scene");
  REQUIRE(scene.cameras.size() == 1);
  const CameraDesc& camera = scene.cameras[0];
  CHECK(camera.lens_radius == 12);
  CHECK(camera.aperture_blades == 6);
  // The distance along the view from (0, 60, 400) to the look-at point (0, 40, 0).
  CHECK(camera.focus_distance == Approx(std::sqrt(400.0 * 400 + 20 * 20)));
  CHECK(scene.shapes.size() == 6);
}

TEST_CASE("asset panorama.scene: an equirectangular camera inside a ring of bodies") {
  SceneDesc scene = load_asset("panorama.scene");
  REQUIRE(scene.cameras.size() == 1);
  CHECK(scene.cameras[0].projection == Projection::equirectangular);
  CHECK(scene.cameras[0].aspect == 2);
  CHECK(scene.cameras[0].width == 512);
  CHECK(scene.shapes.size() == 7);
}

TEST_CASE("asset room-older-format.scene: six walls, an emitting sphere, a mirror sphere") {
  SceneDesc scene = load_asset("room-older-format.scene");
  int walls = 0, emitting = 0, mirrors = 0, diffuse_spheres = 0;
  for (const ShapeDesc& shape : scene.shapes) {
    const MaterialDesc& material = scene.materials.at(size_t(shape.material));
    walls += shape.kind == ShapeKind::plane;
    if (shape.kind != ShapeKind::sphere) continue;
    emitting += !is_black(material.emission);
    mirrors += !is_black(material.kr);
    diffuse_spheres += is_black(material.emission) && is_black(material.kr);
  }
  CHECK(walls == 6);
  CHECK(emitting == 1);
  CHECK(mirrors == 1);
  CHECK(diffuse_spheres == 2);
  CHECK(scene.cameras.size() == 1);
  CHECK(scene.lights.empty());
}

TEST_CASE("asset many-lights.scene: 400 small emissive quads (800 triangles) over a floor with six balls") {
  SceneDesc scene = load_asset("many-lights.scene");
  size_t lamp_triangles = 0;
  for (const InstanceDesc& instance : scene.instances) {
    const MeshDesc& mesh = scene.meshes.at(size_t(instance.mesh));
    if (mesh.material >= 0 && !is_black(scene.materials.at(size_t(mesh.material)).emission))
      lamp_triangles += mesh.triangle_count();
  }
  CHECK(lamp_triangles == 2 * 400);
  CHECK(scene.lights.empty());
  CHECK(scene.shapes.size() == 7);  // the floor and six balls
  CHECK(scene.settings.mode == RenderMode::path);
}
