// Depth of field and panoramic cameras in whole renders: the circle of confusion of a small
// light, panoramas of a white furnace, and images independent of the thread count.
#include <doctest/doctest.h>

#include <cmath>

#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

RenderOptions path_options(int width, int height, int spp) {
  RenderOptions o;
  o.width = width;
  o.height = height;
  o.spp = spp;
  o.mode = RenderMode::path;
  o.quiet = true;
  o.env_preset = EnvironmentPreset::none;  // glowing spheres on black, not the default studio
  return o;
}

// A small glowing sphere of radius 0.02 at distance `distance` straight ahead of a camera whose
// film spans tan(half fov) = 0.1 over 32 pixels from the centre.
SceneDesc small_light_ahead(float distance, float lens_radius, float focus_distance, int blades = 0) {
  SceneDesc scene;
  MaterialDesc glow;
  glow.emission = {1, 1, 1};
  add_sphere(scene, {0, 0, -distance}, 0.02f, add_material(scene, glow));
  CameraDesc camera = perspective_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, float(2 * std::atan(0.1) * 180 / pi));
  camera.lens_radius = lens_radius;
  camera.focus_distance = focus_distance;
  camera.aperture_blades = blades;
  scene.cameras.push_back(camera);
  return scene;
}

// What the light leaves on the film. Outside the circle of confusion no ray can reach the
// sphere, so unlit pixels are exactly 0 whatever the noise.
struct Spot {
  double total = 0;  // the sum over the image: the light's flux through the film
  double rms_radius = 0;  // sqrt(2 E[r^2]) of the light's distribution: the radius of a uniform disk
  int lit_pixels = 0;
  double above = 0, below = 0, left = 0, right = 0;  // lit extent from the centre, in pixels
  double skew_x = 0, skew_y = 0;  // E[d^3] / E[d^2]^1.5 along each axis (image y down): 0 when symmetric
};

Spot measure(const Film& film) {
  Spot s;
  double cx = film.width / 2.0, cy = film.height / 2.0, moment = 0, x2 = 0, x3 = 0, y2 = 0, y3 = 0;
  for (int y = 0; y < film.height; ++y)
    for (int x = 0; x < film.width; ++x) {
      double v = pixel_mean(film.at(x, y)).x, dx = x + 0.5 - cx, dy = y + 0.5 - cy;
      if (v <= 0) continue;
      s.total += v;
      moment += v * (dx * dx + dy * dy);
      x2 += v * dx * dx, x3 += v * dx * dx * dx, y2 += v * dy * dy, y3 += v * dy * dy * dy;
      s.lit_pixels++;
      s.left = std::max(s.left, -dx), s.right = std::max(s.right, dx);
      s.above = std::max(s.above, -dy), s.below = std::max(s.below, dy);
    }
  s.rms_radius = std::sqrt(2 * moment / s.total);
  s.skew_x = (x3 / s.total) / std::pow(x2 / s.total, 1.5);
  s.skew_y = (y3 / s.total) / std::pow(y2 / s.total, 1.5);
  return s;
}

// The rms radius of a disk of radius `coc` blurred by the sphere's disk of 1.6 pixels and by
// the pixels' own width (1/12 per axis): the second moments add.
double blurred_radius(double coc) { return std::sqrt(coc * coc + 1.6 * 1.6 + 1.0 / 3); }

}  // namespace

TEST_CASE("depth of field: a point out of focus spreads into the circle of confusion R |1/D - 1/F|, keeping its flux") {
  RenderOptions o = path_options(64, 64, 128);
  o.max_depth = 1;
  // In focus at D = 4: a disk of the sphere's own size, 0.02/4 in tan units = 1.6 pixels.
  Spot sharp = measure(render_scene(small_light_ahead(4, 0.1f, 4), o).film);
  CHECK(sharp.rms_radius == doctest::Approx(blurred_radius(0)).epsilon(0.05));
  // Focused at F = 2: the blur radius is 0.1 * |1/4 - 1/2| = 0.025 in tan units, 8 pixels.
  Spot nearer = measure(render_scene(small_light_ahead(4, 0.1f, 2), o).film);
  CHECK(nearer.rms_radius == doctest::Approx(blurred_radius(8)).epsilon(0.03));
  CHECK(nearer.right <= 8 + 1.6 + 0.6);  // nothing beyond the circle (pixel centres lie 0.5 inside a pixel)
  CHECK(nearer.right >= 8);
  // Focused beyond (F = 8): 0.1 * |1/4 - 1/8| = 4 pixels.
  Spot beyond = measure(render_scene(small_light_ahead(4, 0.1f, 8), o).film);
  CHECK(beyond.rms_radius == doctest::Approx(blurred_radius(4)).epsilon(0.03));
  // The lens moves light around the film, it neither makes nor loses any.
  CHECK(nearer.total == doctest::Approx(sharp.total).epsilon(0.03));
  CHECK(beyond.total == doctest::Approx(sharp.total).epsilon(0.03));
}

TEST_CASE("depth of field: three blades make a triangular bokeh, corner up beyond the focus, inverted before it") {
  RenderOptions o = path_options(64, 64, 128);
  o.max_depth = 1;
  // A point at distance D lands on the film at its pinhole position + l (1/F - 1/D) for the lens
  // point l: beyond the focus (D = 4, F = 2) the aperture's image is upright, 0.2 * 1/4 = 0.05 in tan
  // units (16 pixels) to its corners; before it (F = 8) inverted, 0.2 * 1/8 (8 pixels).
  Spot beyond = measure(render_scene(small_light_ahead(4, 0.2f, 2, 3), o).film);
  Spot before = measure(render_scene(small_light_ahead(4, 0.2f, 8, 3), o).film);
  Spot round = measure(render_scene(small_light_ahead(4, 0.2f, 2), o).film);
  // An equilateral triangle's skewness towards its corner is 9/320 / (1/8)^1.5 = 0.566; the
  // sphere's own disk (variance 1.6^2 / 4) and the pixels (1/12) lower it to 0.547 at 16 pixels.
  CHECK(beyond.skew_y == doctest::Approx(-0.547).epsilon(0.08));  // image y runs down: the corner is up
  CHECK(std::abs(beyond.skew_x) < 0.15);
  CHECK(before.skew_y > 0.4);  // the corner points down
  CHECK(std::abs(round.skew_y) < 0.15);  // a disk is symmetric (up to the noise of a third moment)
  // The flat side is half as far from the centre as the corner (plus the sphere's 1.6 pixels).
  CHECK(beyond.below == doctest::Approx(8 + 1.6).epsilon(0.1));
  CHECK(beyond.above > beyond.below + 4);
  CHECK(beyond.total == doctest::Approx(round.total).epsilon(0.03));
}

TEST_CASE("depth of field and panoramas: the same image at any thread count") {
  SceneDesc lens_scene = small_light_ahead(4, 0.1f, 2, 5);
  add_plane(lens_scene, {0, -1, 0}, {0, 1, 0}, add_diffuse(lens_scene, {0.5f, 0.5f, 0.5f}));
  SceneDesc fisheye_scene = lens_scene;
  fisheye_scene.cameras[0].lens_radius = 0;
  fisheye_scene.cameras[0].projection = Projection::fisheye;
  for (const SceneDesc& scene : {lens_scene, fisheye_scene}) {
    RenderOptions o = path_options(24, 16, 8);
    o.env_color = color3{0.2f, 0.3f, 0.4f};
    o.threads = 1;
    Film one = render_scene(scene, o).film;
    o.threads = 3;
    Film three = render_scene(scene, o).film;
    for (size_t i = 0; i < one.pixels.size(); ++i) REQUIRE(pixel_mean(one.pixels[i]) == pixel_mean(three.pixels[i]));
  }
}

TEST_CASE("panoramas: a white furnace seen all around is 1.0 in every pixel, a fisheye's corners black") {
  SceneDesc scene;
  add_sphere(scene, {0, 0, -3}, 1, add_diffuse(scene, {1, 1, 1}));
  add_sphere(scene, {2, 1, 2}, 0.5f, add_diffuse(scene, {1, 1, 1}));
  scene.cameras.push_back(perspective_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 40));
  RenderOptions o = path_options(32, 16, 64);
  o.env_color = color3{1, 1, 1};
  o.max_depth = 16;
  SUBCASE("equirectangular") {
    scene.cameras[0].projection = Projection::equirectangular;
    Film film = render_scene(scene, o).film;
    for (const FilmPixel& p : film.pixels) REQUIRE(pixel_mean(p).x == doctest::Approx(1).epsilon(0.02));
  }
  SUBCASE("fisheye") {
    scene.cameras[0].projection = Projection::fisheye;
    Film film = render_scene(scene, o).film;
    // The circle has radius 8 pixels around (16, 8): pixels wholly inside see the furnace, pixels
    // wholly outside see nothing.
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 32; ++x) {
        double nearest = std::hypot(std::max(0.0, std::abs(x + 0.5 - 16) - 0.5), std::max(0.0, std::abs(y + 0.5 - 8) - 0.5));
        double farthest = std::hypot(std::abs(x + 0.5 - 16) + 0.5, std::abs(y + 0.5 - 8) + 0.5);
        float v = pixel_mean(film.at(x, y)).x;
        if (farthest <= 8) REQUIRE(v == doctest::Approx(1).epsilon(0.02));
        if (nearest > 8) REQUIRE(v == 0);
      }
  }
}
