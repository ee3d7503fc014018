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
