// The framing camera of a file without one: the whole bounding box in view, seen across its
// largest extents (never a flat model edge on).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "render/camera.h"
#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// The largest of |x| / half-width and |y| / half-height over the box's corners in `camera`'s
// view (1 = on the image border), in an image of width / height `aspect`.
float widest_corner(const CameraDesc& camera, vec3 lower, vec3 upper, float aspect) {
  CameraFrame frame = make_camera_frame(camera, int(std::lround(64 * aspect)), 64);
  float widest = 0;
  for (int corner = 0; corner < 8; ++corner) {
    vec3 p = {corner & 1 ? upper.x : lower.x, corner & 2 ? upper.y : lower.y, corner & 4 ? upper.z : lower.z};
    vec3 d = p - frame.position;
    float depth = dot(d, frame.forward);
    REQUIRE(depth > 0);
    widest = std::max({widest, std::abs(dot(d, frame.right)) / depth / frame.half_width,
                       std::abs(dot(d, frame.up)) / depth / frame.half_height});
  }
  return widest;
}

}  // namespace

TEST_CASE("framing camera: every corner of the box is in view, with a small margin, at any aspect") {
  struct Box {
    vec3 lower, upper;
  };
  for (Box box : {Box{{-1, -1, -1}, {1, 1, 1}}, Box{{0, 0, 0}, {10, 1, 2}}, Box{{-3, 0, 5}, {-2, 8, 5.5f}},
                  Box{{100, 100, 100}, {100.5f, 101, 100.2f}}})
    for (float aspect : {1.0f, 2.0f, 0.5f}) {
      CameraDesc camera = frame_box(box.lower, box.upper, aspect);
      float widest = widest_corner(camera, box.lower, box.upper, aspect);
      CAPTURE(aspect);
      CAPTURE(box.upper.x);
      CHECK(widest <= 1);
      CHECK(widest > 0.9f);  // not just far away: the box fills the view
    }
}

TEST_CASE("framing camera: from the front unless another side shows much more of the box") {
  vec3 front = normalize(vec3{0, 0.25f, 1});
  // A cube and a long low box (a car) keep the front view.
  CHECK(frame_box({-1, -1, -1}, {1, 1, 1}, 1).forward == -front);
  CHECK(frame_box({-2, 0, -1}, {2, 1.5f, 1}, 1).forward == -front);
  // A polygon in a plane x = const (concave_polygon.obj) is seen from +x, a floor from above.
  CameraDesc side = frame_box({-1.146f, 1.65f, 1.8f}, {-1.146f, 3.1f, 2.9f}, 1);
  CHECK(side.forward.x < -0.9f);
  CameraDesc above = frame_box({-5, 0, -5}, {5, 0, 5}, 1);
  CHECK(above.forward.y < -0.9f);
}

TEST_CASE("framing camera: a flat model in the x = const plane fills the framed image") {
  // The old camera looked along -z: it saw this square edge on, as nothing.
  SceneDesc scene;
  add_quad(scene, {-1.146f, 1, 1}, {-1.146f, 3, 1}, {-1.146f, 3, 3}, {-1.146f, 1, 3}, add_diffuse(scene, {1, 1, 1}));
  LightDesc light;
  light.kind = LightKind::directional;
  light.direction = {-1, 0, 0};
  scene.lights.push_back(light);
  RenderOptions o;
  o.width = 32, o.height = 24, o.spp = 1, o.mode = RenderMode::whitted;
  RenderResult result = render_scene(scene, o);
  CHECK(result.settings.camera_framed);
  int lit = 0;
  for (const FilmPixel& pixel : result.film.pixels) lit += pixel_mean(pixel).x > 0;
  CHECK(lit > int(result.film.pixels.size()) / 3);
}

TEST_CASE("framing camera: --up +Z frames a z-up model as a y-up one, from -y, upright") {
  // The same box, tall along y in a y-up world and tall along z in a z-up one.
  CameraDesc y_up = frame_box({-1, 0, -0.5f}, {1, 3, 0.5f}, 1);
  CameraDesc z_up = frame_box({-1, -0.5f, 0}, {1, 0.5f, 3}, 1, {0, 0, 1});
  CHECK(z_up.up.z == doctest::Approx(y_up.up.y));
  CHECK(z_up.position.y == doctest::Approx(-y_up.position.z));  // the front of a z-up file is -y
  CHECK(z_up.position.z == doctest::Approx(y_up.position.y));
  CHECK(z_up.position.x == doctest::Approx(y_up.position.x));
  CHECK(widest_corner(z_up, {-1, -0.5f, 0}, {1, 0.5f, 3}, 1) == doctest::Approx(widest_corner(y_up, {-1, 0, -0.5f}, {1, 3, 0.5f}, 1)));
}

TEST_CASE("framing camera: --orbit turns the view about the box's centre, keeping all of it in view") {
  vec3 lower{-1, -1, -1}, upper{1, 1, 1};
  CameraDesc front = frame_box(lower, upper, 1);
  CameraDesc right = frame_box(lower, upper, 1, {0, 1, 0}, Orbit{90, 0, 1});
  // Counterclockwise seen from above: the camera in front (+z) moves to +x, at the same height.
  CHECK(right.position.x == doctest::Approx(length(vec3{front.position.x, 0, front.position.z})));
  CHECK(right.position.z == doctest::Approx(0).epsilon(1e-5).scale(1));
  CHECK(right.position.y == doctest::Approx(front.position.y));
  CameraDesc above = frame_box(lower, upper, 1, {0, 1, 0}, Orbit{0, 60, 1});
  CHECK(std::asin(above.position.y / length(above.position)) * 180 / pi ==
        doctest::Approx(std::asin(front.position.y / length(front.position)) * 180 / pi + 60).epsilon(1e-3));
  for (CameraDesc camera : {right, above}) CHECK(widest_corner(camera, lower, upper, 1) <= 1);
  CameraDesc farther = frame_box(lower, upper, 1, {0, 1, 0}, Orbit{0, 0, 2});
  CHECK(length(farther.position) == doctest::Approx(2 * length(front.position)));
}

TEST_CASE("framing camera: --camera frame picks it even when the file has cameras") {
  std::vector<CameraDesc> cameras = {perspective_camera({0, 0, 9}, {0, 0, -1}, {0, 1, 0}, 30)};
  cameras[0].name = "file";
  CameraDesc framing = frame_box({-1, -1, -1}, {1, 1, 1}, 1);
  bool framed = false;
  CHECK(select_camera(cameras, framing, "frame", framed).name == "framing");
  CHECK(framed);
  CHECK(select_camera(cameras, framing, "", framed).name == "file");
  CHECK_FALSE(framed);
}
