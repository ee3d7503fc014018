// Camera rays of the thin lens and the panoramic projections, checked against their geometry.
#include <doctest/doctest.h>

#include <cmath>

#include "render/camera.h"
#include "sampling/warp.h"

using namespace radiant;

namespace {

CameraDesc looking_down_minus_z(Projection projection) {
  CameraDesc c;
  c.projection = projection;
  c.position = {1, 2, 3};
  c.forward = {0, 0, -1};
  c.up = {0, 1, 0};
  c.vertical_fov_degrees = 40;
  return c;
}

// Lens samples on a 16 x 16 grid of cell centres.
std::vector<vec2> lens_grid() {
  std::vector<vec2> points;
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j) points.push_back({(i + 0.5f) / 16, (j + 0.5f) / 16});
  return points;
}

}  // namespace

TEST_CASE("thin lens: every ray of a film position meets the pinhole ray on the plane in focus, leaving the aperture") {
  CameraDesc camera = looking_down_minus_z(Projection::perspective);
  CameraFrame pinhole = make_camera_frame(camera, 32, 24);
  camera.lens_radius = 0.25f;
  camera.focus_distance = 5;
  CameraFrame lens = make_camera_frame(camera, 32, 24);
  for (auto [x, y] : {std::pair{16.0f, 12.0f}, {3.5f, 20.25f}, {31.0f, 0.5f}}) {
    Ray center = *generate_camera_ray(pinhole, x, y);
    vec3 in_focus = center.origin + center.direction * (5 / -center.direction.z);  // the plane z = 3 - 5
    float farthest = 0;
    for (vec2 u : lens_grid()) {
      Ray r = *generate_camera_ray(lens, x, y, u);
      vec3 offset = r.origin - camera.position;
      CHECK(offset.z == doctest::Approx(0).epsilon(1e-6));  // the lens lies across the view direction
      CHECK(length(offset) <= 0.25f * 1.0001f);
      farthest = std::max(farthest, length(offset));
      vec3 hit = r.origin + r.direction * (5 / -r.direction.z);
      CHECK(hit.x == doctest::Approx(in_focus.x).epsilon(1e-4));
      CHECK(hit.y == doctest::Approx(in_focus.y).epsilon(1e-4));
    }
    CHECK(farthest > 0.23f);  // the samples reach the rim
  }
  // A pinhole (lens radius 0) ignores the lens sample.
  Ray a = *generate_camera_ray(pinhole, 5, 6, {0.1f, 0.9f}), b = *generate_camera_ray(pinhole, 5, 6);
  CHECK(a.origin == b.origin);
  CHECK(a.direction == b.direction);
}

TEST_CASE("thin lens: an orthographic camera focuses too, on the plane at the focus distance") {
  CameraDesc camera = looking_down_minus_z(Projection::orthographic);
  camera.ortho_height = 2;
  camera.lens_radius = 0.1f;
  camera.focus_distance = 4;
  CameraFrame frame = make_camera_frame(camera, 16, 16);
  // Film x = 10 of 16 across a view 2 wide centred on x = 1: the pinhole ray runs along x = 1.25.
  for (vec2 u : lens_grid()) {
    Ray r = *generate_camera_ray(frame, 10, 8, u);
    vec3 hit = r.origin + r.direction * (4 / -r.direction.z);
    CHECK(hit.x == doctest::Approx(1 + (2 * 10.0f / 16 - 1)).epsilon(1e-4));
    CHECK(hit.y == doctest::Approx(2).epsilon(1e-4));
  }
}

TEST_CASE("aperture shapes: the disk and the regular polygon are filled uniformly and never left") {
  // Uniform: the share of points inside a centred circle of radius 1/2 is its share of the area.
  auto inner_share = [](auto sample, float inner_radius) {
    int inside = 0, n = 0;
    for (int i = 0; i < 200; ++i)
      for (int j = 0; j < 200; ++j, ++n) {
        vec2 p = sample(vec2{(i + 0.5f) / 200, (j + 0.5f) / 200});
        inside += std::hypot(p.x, p.y) < inner_radius;
      }
    return double(inside) / n;
  };
  CHECK(inner_share([](vec2 u) { return sample_uniform_disk(u); }, 0.5f) == doctest::Approx(0.25).epsilon(0.01));
  for (int corners : {3, 5, 6, 8}) {
    float apothem = std::cos(pi / corners), area = 0.5f * corners * std::sin(2 * pi / corners);
    float r = 0.5f * apothem;  // a circle inside the polygon
    CHECK(inner_share([&](vec2 u) { return sample_regular_polygon(u, corners); }, r) ==
          doctest::Approx(pi * r * r / area).epsilon(0.01));
    for (int i = 0; i < 64; ++i)
      for (int j = 0; j < 64; ++j) {
        vec2 p = sample_regular_polygon({(i + 0.5f) / 64, (j + 0.5f) / 64}, corners);
        // Inside every edge: the edge normals point between consecutive corners (one corner at +y).
        for (int k = 0; k < corners; ++k) {
          float a = pi / 2 + (2 * pi / corners) * (k + 0.5f);
          CHECK(p.x * std::cos(a) + p.y * std::sin(a) <= apothem * 1.0001f);
        }
      }
  }
}

TEST_CASE("equirectangular: longitude across the image from behind to behind, latitude from up to down") {
  CameraFrame f = make_camera_frame(looking_down_minus_z(Projection::equirectangular), 64, 32);
  auto direction = [&](float x, float y) { return normalize(generate_camera_ray(f, x, y)->direction); };
  vec3 center = direction(32, 16), right = direction(48, 16), left = direction(16, 16);
  CHECK(center.z == doctest::Approx(-1));
  CHECK(right.x == doctest::Approx(1));   // a quarter turn to the right of the view
  CHECK(left.x == doctest::Approx(-1));
  CHECK(direction(0, 16).z == doctest::Approx(1));  // the edges look behind
  CHECK(direction(32, 0).y == doctest::Approx(1));  // the top row looks up
  CHECK(direction(10, 32).y == doctest::Approx(-1));
  // Equal steps of latitude: the row a quarter down looks 45 degrees up.
  CHECK(direction(32, 8).y == doctest::Approx(std::sqrt(0.5f)));
  CHECK(f.lens_radius == 0);
}

TEST_CASE("fisheye: equidistant, the half field of view on the inscribed circle, nothing outside it") {
  CameraDesc camera = looking_down_minus_z(Projection::fisheye);
  camera.fisheye_fov_degrees = 180;
  CameraFrame f = make_camera_frame(camera, 40, 20);  // the circle has radius 10 pixels
  CHECK(normalize(generate_camera_ray(f, 20, 10)->direction).z == doctest::Approx(-1));
  vec3 edge = normalize(generate_camera_ray(f, 30, 10)->direction);  // radius 1: 90 degrees
  CHECK(edge.x == doctest::Approx(1));
  vec3 half = normalize(generate_camera_ray(f, 20, 5)->direction);  // radius 1/2 up: 45 degrees
  CHECK(half.y == doctest::Approx(std::sqrt(0.5f)));
  CHECK(half.z == doctest::Approx(-std::sqrt(0.5f)));
  CHECK_FALSE(generate_camera_ray(f, 31, 10).has_value());
  CHECK_FALSE(generate_camera_ray(f, 2, 1).has_value());
  camera.fisheye_fov_degrees = 360;  // a whole-sphere fisheye sees behind on its rim
  CHECK(normalize(generate_camera_ray(make_camera_frame(camera, 40, 20), 30, 10)->direction).z ==
        doctest::Approx(1));
}

TEST_CASE("camera override: --camera-type, --fov of a fisheye and the lens flags, with their errors") {
  CameraDesc camera = looking_down_minus_z(Projection::perspective);
  CameraOverride o;
  o.projection = Projection::fisheye;
  o.fov_degrees = 200;
  CameraDesc fisheye = camera;
  apply_camera_override(fisheye, o);
  CHECK(fisheye.projection == Projection::fisheye);
  CHECK(fisheye.fisheye_fov_degrees == 200);
  CHECK(fisheye.aspect == 1);
  o.projection = Projection::equirectangular;
  CameraDesc equirect = camera;
  CHECK_THROWS_WITH_AS(apply_camera_override(equirect, o),
                       "--fov does not apply to an equirectangular camera (it sees all around)", std::invalid_argument);
  CameraOverride lens;
  lens.lens_radius = 0.1f;
  CameraDesc unfocused = camera;
  CHECK_THROWS_WITH_AS(apply_camera_override(unfocused, lens),
                       "a lens (--lens-radius) needs a focus distance: --focus-distance D, or --look-at",
                       std::invalid_argument);
  lens.look_at = vec3{1, 2, -4};  // 7 in front of the camera
  CameraDesc focused = camera;
  apply_camera_override(focused, lens);
  CHECK(focused.focus_distance == doctest::Approx(7));
  lens.focus_distance = 2.5f;
  apply_camera_override(focused, lens);
  CHECK(focused.focus_distance == 2.5f);
  lens.projection = Projection::equirectangular;
  CHECK_THROWS_WITH_AS(apply_camera_override(focused, lens),
                       "a lens (--lens-radius) needs a perspective or orthographic camera", std::invalid_argument);
}
