// KHR_lights_punctual (1:1 radiometric) and glTF cameras, placed by their nodes.
#include <doctest/doctest.h>

#include "loaders/gltf_builder.h"
#include "load_scene.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

static SceneDesc load_body(const std::string& body) {
  ScratchDir dir("gltf-lights");
  return load_scene(dir.write("scene.gltf", quad_builder().gltf(std::string(quad_mesh) + "," + body)).string());
}

TEST_CASE("gltf lights: point, spot and directional keep their units and take the node's frame") {
  SceneDesc scene = load_body(
      "\"extensionsUsed\":[\"KHR_lights_punctual\"],\"extensions\":{\"KHR_lights_punctual\":{\"lights\":["
      "{\"type\":\"point\",\"color\":[1,0.5,0.25],\"intensity\":100,\"range\":20,\"name\":\"bulb\"},"
      "{\"type\":\"spot\",\"intensity\":8,\"spot\":{\"innerConeAngle\":0.2,\"outerConeAngle\":0.5}},"
      "{\"type\":\"directional\",\"intensity\":3}]}},"
      "\"nodes\":[{\"mesh\":0},{\"translation\":[1,2,3],\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}}},"
      "{\"translation\":[0,5,0],\"rotation\":[-0.70710678,0,0,0.70710678],"
      "\"extensions\":{\"KHR_lights_punctual\":{\"light\":1}}},"
      "{\"extensions\":{\"KHR_lights_punctual\":{\"light\":2}}}],\"scenes\":[{\"nodes\":[0,1,2,3]}]");
  REQUIRE(scene.lights.size() == 3);
  const LightDesc& point = scene.lights[0];
  CHECK(point.kind == LightKind::point);
  CHECK(point.name == "bulb");
  CHECK(point.intensity.x == 100);  // 100 cd -> 100 W/sr
  CHECK(point.intensity.z == 25);
  CHECK(point.position.y == 2);
  CHECK(point.kq == 1);
  CHECK(point.kc == 0);
  CHECK(point.range == 20);
  const LightDesc& spot = scene.lights[1];
  CHECK(spot.kind == LightKind::spot);
  CHECK(spot.use_cone);
  CHECK(spot.inner_cone == doctest::Approx(0.2));
  CHECK(spot.outer_cone == doctest::Approx(0.5));
  CHECK(spot.direction.y == doctest::Approx(-1));  // -Z rotated by -90 degrees about X points down
  const LightDesc& sun = scene.lights[2];
  CHECK(sun.kind == LightKind::directional);
  CHECK(sun.intensity.y == 3);  // 3 lux -> 3 W/m^2
  CHECK(sun.direction.z == -1);
}

TEST_CASE("gltf cameras: perspective and orthographic, scale removed, visit order kept") {
  SceneDesc scene = load_body(
      "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.5,\"aspectRatio\":1.5,\"znear\":0.1}},"
      "{\"type\":\"orthographic\",\"name\":\"top\",\"orthographic\":{\"xmag\":4,\"ymag\":2,\"znear\":0,\"zfar\":9}}],"
      "\"nodes\":[{\"mesh\":0,\"children\":[2]},{\"camera\":1,\"translation\":[0,10,0],"
      "\"rotation\":[-0.70710678,0,0,0.70710678]},{\"name\":\"eye\",\"camera\":0,\"translation\":[0,0,5],"
      "\"scale\":[3,3,3]}],\"scenes\":[{\"nodes\":[0,1]}]");
  REQUIRE(scene.cameras.size() == 2);
  const CameraDesc& eye = scene.cameras[0];
  CHECK(eye.name == "eye");
  CHECK(eye.projection == Projection::perspective);
  CHECK(eye.vertical_fov_degrees == doctest::Approx(0.5 * 180 / 3.14159265));
  CHECK(eye.aspect == doctest::Approx(1.5));
  CHECK(eye.position.z == 5);
  CHECK(eye.forward.z == doctest::Approx(-1));
  CHECK(eye.up.y == doctest::Approx(1));  // unit despite the node's scale
  const CameraDesc& top = scene.cameras[1];
  CHECK(top.name == "top");
  CHECK(top.projection == Projection::orthographic);
  CHECK(top.ortho_height == 4);
  CHECK(top.aspect == 2);
  CHECK(top.forward.y == doctest::Approx(-1));
  CHECK(top.up.z == doctest::Approx(-1));
}

TEST_CASE("gltf lights: a bad light reference names the node") {
  ScratchDir dir("gltf-light-error");
  std::string path = dir.write("l.gltf", quad_builder().gltf(std::string(quad_mesh) +
      ",\"nodes\":[{\"mesh\":0,\"extensions\":{\"KHR_lights_punctual\":{\"light\":4}}}],\"scenes\":[{\"nodes\":[0]}]")).string();
  CHECK_THROWS_WITH_AS(load_scene(path),
                       (path + ": nodes[0].extensions.KHR_lights_punctual.light: light 4 out of range (0 lights)").c_str(),
                       LoadError);
}
