// A camera whose up vector is parallel to its view direction (docs/stability.md, case 4):
// an explicit --up is an error; an authored up falls back to +y (or -z when looking along y),
// and the render never sees a degenerate frame.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>

#include "render/camera.h"
#include "stability/film_checks.h"

using namespace radiant;
using namespace radiant::test;

namespace {

std::string override_error(CameraDesc camera, const CameraOverride& o) {
  try {
    apply_camera_override(camera, o);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

void check_orthonormal(const CameraDesc& c) {
  CHECK(is_finite(c.up));
  CHECK(length(c.up) == doctest::Approx(1).epsilon(1e-6));
  CHECK(std::abs(dot(c.up, c.forward)) < 1e-6f);
}

}  // namespace

TEST_CASE("camera up: an explicit --up parallel or anti-parallel to the view direction is an error") {
  CameraDesc camera;
  CameraOverride o;
  o.look_from = vec3{0, 5, 0};
  o.look_at = vec3{0, 0, 0};  // looking along -y
  for (vec3 up : {vec3{0, 1, 0}, vec3{0, -1, 0}, vec3{0, 3, 0}, vec3{1e-7f, 1, 0}}) {
    CAPTURE(up.x);
    CAPTURE(up.y);
    o.up = up;
    CHECK(override_error(camera, o) == "--up is parallel to the view direction");
  }
  // Only the up flag, against the camera's own direction.
  CameraOverride up_only;
  up_only.up = camera.forward;
  CHECK(override_error(camera, up_only) == "--up is parallel to the view direction");
}

TEST_CASE("camera up: an authored up parallel to the view falls back to +y, or to -z when looking along y") {
  CameraDesc down;
  down.forward = {0, -1, 0};
  down.up = {0, -1, 0};
  apply_camera_override(down, {});
  check_orthonormal(down);
  CHECK(down.up == vec3{0, 0, -1});

  CameraDesc sideways;
  sideways.forward = {1, 0, 0};
  sideways.up = {1, 0, 0};
  apply_camera_override(sideways, {});
  check_orthonormal(sideways);
  CHECK(sideways.up == vec3{0, 1, 0});
}

TEST_CASE("camera up: a scene camera with up parallel to its view renders the same image as with the fallback up") {
  SceneDesc scene;
  int m = add_diffuse(scene, {0.5f, 0.5f, 0.5f});
  add_plane(scene, {0, 0, 0}, {0, 1, 0}, m);
  add_sphere(scene, {0.5f, 0.5f, -0.3f}, 0.5f, m);  // off centre, so that orientation matters
  scene.lights.push_back(point_light({1, 3, 1}, {10, 10, 10}));
  scene.cameras.push_back(perspective_camera({0, 4, 0}, {0, -1, 0}, {0, -1, 0}, 60));
  RenderResult degenerate = render_finite(scene, whitted_options(16));
  scene.cameras[0].up = {0, 0, -1};
  RenderResult fallback = render_finite(scene, whitted_options(16));
  FilmDifference d = compare_films(fallback.film, degenerate.film, 0, 0);
  CHECK(d.max_absolute == 0);
}

TEST_CASE("camera up: an explicit zero --up is an error") {
  CameraDesc camera;
  CameraOverride o;
  o.up = vec3{0, 0, 0};
  CHECK_THROWS_AS(apply_camera_override(camera, o), std::invalid_argument);
}
