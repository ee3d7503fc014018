// Motion blur, rendered: a square crossing the view at constant speed leaves the analytic
// coverage profile (a trapezoid), a turning cube blurs symmetrically about its mid-shutter pose,
// a camera pan equals the scene moving the other way, and both integrators, every way of
// batching rays and every sampler agree on what moves.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "sampling/sampler.h"
#include "scene/effects.h"
#include "support/film_measures.h"
#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

int add_glowing(SceneDesc& scene) {
  MaterialDesc glow;
  glow.emission = {1, 1, 1};
  return add_material(scene, glow);
}

// An emitting square, 1 wide, tall enough to fill every row, that moves from x = -2 to x = 2
// while the shutter is open (its rendered pose at x = 0), seen from +z by an orthographic camera
// showing x in [-5, 5] on 80 columns.
SceneDesc crossing_square() {
  SceneDesc scene;
  add_quad(scene, {-0.5f, -2, 0}, {0.5f, -2, 0}, {0.5f, 2, 0}, {-0.5f, 2, 0}, add_glowing(scene));
  scene.instances[0].motion = {translation({-2, 0, 0}), translation({2, 0, 0})};
  scene.cameras.push_back(ortho_camera({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 1));
  return scene;
}

RenderOptions crossing_options(RenderMode mode) {
  RenderOptions o;
  o.width = 80, o.height = 8, o.spp = 64, o.mode = mode, o.env_color = color3{0, 0, 0};
  return o;
}

// The share of the shutter during which point x lies inside the square: the overlap of
// [x - 0.5, x + 0.5] with the centre's path [-2, 2], over the path's length 4.
double coverage_at(double x) { return std::max(0.0, std::min(x + 0.5, 2.0) - std::max(x - 0.5, -2.0)) / 4; }

// Its mean over pixel column `column` (0.125 wide, from x = -5).
double column_coverage(int column) {
  constexpr int steps = 256;
  double sum = 0;
  for (int k = 0; k < steps; ++k) sum += coverage_at(-5 + 0.125 * (column + (k + 0.5) / steps));
  return sum / steps;
}

double column_mean(const Film& film, int column) {
  double sum = 0;
  for (int y = 0; y < film.height; ++y) sum += pixel_mean(film.at(column, y)).x;
  return sum / film.height;
}

// A unit cube centred on the origin, each face two triangles facing out.
void add_cube(SceneDesc& scene, int material) {
  MeshDesc cube;
  cube.material = material;
  for (int corner = 0; corner < 8; ++corner)
    cube.positions.push_back({corner & 1 ? 0.5f : -0.5f, corner & 2 ? 0.5f : -0.5f, corner & 4 ? 0.5f : -0.5f});
  cube.indices = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
  scene.meshes.push_back(cube);
  InstanceDesc instance;
  instance.mesh = int(scene.meshes.size()) - 1;
  scene.instances.push_back(instance);
}

}  // namespace

TEST_CASE("motion blur: a square crossing the view leaves the trapezoid of its coverage, in both integrators") {
  for (RenderMode mode : {RenderMode::whitted, RenderMode::path}) {
    CAPTURE(int(mode));
    SceneDesc scene = crossing_square();
    CHECK(analyze_effects(scene).has(effect_motion_blur));
    RenderResult blurred = render_scene(scene, crossing_options(mode));
    for (int column = 0; column < 80; ++column) {
      CAPTURE(column);
      // 64 stratified times a pixel, over 8 rows: well within 0.02 of the exact share.
      CHECK(std::abs(column_mean(blurred.film, column) - column_coverage(column)) < 0.02);
    }
    CHECK(column_mean(blurred.film, 40) == doctest::Approx(0.25).epsilon(0.05));  // the plateau: 1 of 4
    CHECK(column_mean(blurred.film, 2) == 0);                                      // beyond the streak
  }
}

TEST_CASE("motion blur: camera rays traced alone, in packets and as a batch give the same bits") {
  SceneDesc scene = crossing_square();
  RenderOptions o = crossing_options(RenderMode::path);
  o.spp = 8;
  o.path_batching = PathBatching::none;
  RenderResult alone = render_scene(scene, o);
  for (PathBatching batching : {PathBatching::camera_rays, PathBatching::all_rays}) {
    CAPTURE(int(batching));
    o.path_batching = batching;
    RenderResult together = render_scene(scene, o);
    for (size_t i = 0; i < alone.film.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c) CHECK(together.film.pixels[i].sum[c] == alone.film.pixels[i].sum[c]);
  }
}

TEST_CASE("motion blur: a cube turning through the shutter blurs symmetrically about its mid-shutter pose") {
  SceneDesc scene;
  add_cube(scene, add_glowing(scene));
  // About the view axis: every pose but the mid-shutter one is lopsided left to right.
  for (int k = 0; k < 9; ++k) scene.instances[0].motion.push_back(rotation_axis({0, 0, 1}, -40 + 10 * float(k)));
  scene.cameras.push_back(ortho_camera({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 2));
  RenderOptions o;
  o.width = 48, o.height = 48, o.spp = 64, o.mode = RenderMode::whitted, o.env_color = color3{0, 0, 0};
  RenderResult blurred = render_scene(scene, o);
  // Mirrored left to right, the turn from -40 to 40 degrees is the same turn backwards; a time
  // drawn unevenly over the shutter would favour one side.
  double largest = 0, total_difference = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 24; ++x) {
      double d = std::abs(pixel_mean(blurred.film.at(x, y)).x - pixel_mean(blurred.film.at(47 - x, y)).x);
      largest = std::max(largest, d), total_difference += d;
    }
  CHECK(largest < 0.1);
  CHECK(total_difference / (48 * 24) < 0.01);
  // And it is blurred: the still cube at its mid pose covers whole pixels only.
  SceneDesc still = scene;
  still.instances[0].motion.clear();
  RenderResult sharp = render_scene(still, o);
  CHECK(rms_difference(blurred.film, sharp.film) > 0.05);
  int partial = 0;
  for (const FilmPixel& p : blurred.film.pixels) partial += pixel_mean(p).x > 0.05f && pixel_mean(p).x < 0.95f;
  CHECK(partial > 4 * 24);  // the corners sweep wide bands, not a one-pixel edge
}

TEST_CASE("motion blur: a camera pan blurs a still scene as the scene moving the other way does") {
  SceneDesc moving_scene;
  int glow = add_glowing(moving_scene);
  add_quad(moving_scene, {-1, -1, 0}, {0, -1, 0}, {0, 0.5f, 0}, {-1, 0.5f, 0}, glow);
  add_quad(moving_scene, {0.5f, 0, -1}, {1.5f, 0, -1}, {1.5f, 1, -1}, {0.5f, 1, -1}, glow);
  moving_scene.cameras.push_back(ortho_camera({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 4));
  SceneDesc panning = moving_scene;
  for (InstanceDesc& instance : moving_scene.instances)
    instance.motion = {translation({0.6f, 0, 0}), translation({0, 0, 0}), translation({-0.6f, 0, 0})};
  panning.cameras[0].motion = {{{-0.6f, 0, 5}, {0, 0, -1}, {0, 1, 0}},
                               {{0, 0, 5}, {0, 0, -1}, {0, 1, 0}},
                               {{0.6f, 0, 5}, {0, 0, -1}, {0, 1, 0}}};
  CHECK(analyze_effects(panning).has(effect_motion_blur));
  for (RenderMode mode : {RenderMode::whitted, RenderMode::path}) {
    CAPTURE(int(mode));
    RenderOptions o;
    o.width = 64, o.height = 64, o.spp = 32, o.mode = mode, o.env_color = color3{0, 0, 0};
    RenderResult pan = render_scene(panning, o), moved = render_scene(moving_scene, o);
    // The same times and pixel positions see the same relative placement: equal up to rounding.
    CHECK(rms_difference(pan.film, moved.film) < 0.01);
    SceneDesc still = moving_scene;
    for (InstanceDesc& instance : still.instances) instance.motion.clear();
    CHECK(rms_difference(pan.film, render_scene(still, o).film) > 0.05);  // and it is blurred
  }
}

TEST_CASE("motion blur: --effects -motion-blur renders the rendered time's pose, sharp") {
  SceneDesc scene = crossing_square();
  RenderOptions o = crossing_options(RenderMode::whitted);
  o.effects = "-motion-blur";
  RenderResult sharp = render_scene(scene, o);
  SceneDesc still = scene;
  still.instances[0].motion.clear();
  RenderResult reference = render_scene(still, crossing_options(RenderMode::whitted));
  for (size_t i = 0; i < sharp.film.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) CHECK(sharp.film.pixels[i].sum[c] == reference.film.pixels[i].sum[c]);
}

TEST_CASE("motion blur: a ray's time is stratified over the pixel's samples, and the same in any shard") {
  for (SamplerKind kind : {SamplerKind::jittered, SamplerKind::grid, SamplerKind::sobol}) {
    CAPTURE(int(kind));
    std::vector<int> strata(16, 0);
    for (uint32_t index = 0; index < 16; ++index) {
      SampleContext sample{kind, 77, index, 16, 5};
      float time = sample_time(sample);
      REQUIRE(time >= 0);
      REQUIRE(time < 1);
      strata[size_t(time * 16)]++;
      CHECK(sample_time(sample) == time);  // a pure function of the sample
    }
    for (int count : strata) CHECK(count == 1);
  }
}
