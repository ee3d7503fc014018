// Light shut inside closed objects stays inside, and a closed emitting diffuse sphere never
// returns more than the geometric series allows (docs/stability.md, cases 3 and 5).
#include <doctest/doctest.h>

#include <cmath>

#include "stability/film_checks.h"
#include "stability/scene_pieces.h"

using namespace radiant;
using namespace radiant::test;

namespace {

constexpr int image_size = 16;
constexpr float grey = 0.5f;

// A grey plane y = 0 seen from above and the side: every pixel of the view is the plane or the
// object on it. With ambient light, `ambient` gives every grey pixel ka * ambient.
SceneDesc grey_ground(vec3 offset, float ambient, int& material) {
  SceneDesc scene;
  MaterialDesc m;
  m.kd = {grey, grey, grey};
  m.ka = {grey, grey, grey};
  material = add_material(scene, m);
  add_plane(scene, offset, {0, 1, 0}, material);
  if (ambient > 0) {
    LightDesc a;
    a.kind = LightKind::ambient;
    a.intensity = {ambient, ambient, ambient};
    scene.lights.push_back(a);
  }
  vec3 eye = {0, 4, 3};
  scene.cameras.push_back(perspective_camera(eye + offset, vec3{0, 0.5f, 0} - eye, {0, 1, 0}, 60));
  return scene;
}

// Asserts every pixel equals `value` exactly (within float rounding of one product).
void check_every_pixel(const Film& film, float value) {
  int off = 0;
  for (const FilmPixel& p : film.pixels) {
    color3 c = pixel_mean(p);
    off += std::abs(c.x - value) > 1e-6f || std::abs(c.y - value) > 1e-6f || std::abs(c.z - value) > 1e-6f;
  }
  CHECK(off == 0);
}

// An emitter of radiance 10 shut inside a closed grey object on the ground.
enum class Enclosure { sphere_in_sphere, box_in_box };

SceneDesc shut_emitter(Enclosure kind, int& material) {
  SceneDesc scene = grey_ground({0, 0, 0}, 0, material);
  MaterialDesc emitter;
  emitter.emission = {10, 10, 10};
  int e = add_material(scene, emitter);
  if (kind == Enclosure::sphere_in_sphere) {
    add_sphere(scene, {0, 1, 0}, 1, material);
    add_sphere(scene, {0, 1, 0}, 0.3f, e);
  } else {
    add_box(scene, {-1, 0, -1}, {2, 2, 2}, material);
    add_box(scene, {-0.3f, 0.7f, -0.3f}, {0.6f, 0.6f, 0.6f}, e);
  }
  return scene;
}

}  // namespace

TEST_CASE("enclosure: a point light inside a closed opaque sphere leaves only the ambient term outside, near and far") {
  for (float offset : {0.0f, 1e5f}) {
    CAPTURE(offset);
    vec3 shift = {offset, offset, offset};
    int m;
    SceneDesc scene = grey_ground(shift, 0.1f, m);
    add_sphere(scene, vec3{0, 1.5f, 0} + shift, 1, m);
    scene.lights.push_back(point_light(vec3{0, 1.5f, 0} + shift, {50, 50, 50}));
    check_every_pixel(render_finite(scene, whitted_options(image_size)).film, grey * 0.1f);
    scene.lights.erase(scene.lights.begin());  // no ambient light in the path tracer's world
    check_every_pixel(render_finite(scene, path_options(image_size, 16, 4)).film, 0);
  }
}

TEST_CASE("enclosure: an emitter inside a closed diffuse sphere or box lights nothing outside, in either mode") {
  for (Enclosure kind : {Enclosure::sphere_in_sphere, Enclosure::box_in_box}) {
    CAPTURE(int(kind));
    int m;
    SceneDesc scene = shut_emitter(kind, m);
    check_every_pixel(render_finite(scene, whitted_options(image_size)).film, 0);
    check_every_pixel(render_finite(scene, path_options(image_size, 16, 5)).film, 0);
  }
}

namespace {

// Mean over the film of the inside of a closed sphere of reflectance kd emitting `emitted`.
double furnace_mean(float kd, float emitted, int depth) {
  SceneDesc scene;
  MaterialDesc wall;
  wall.kd = {kd, kd, kd};
  wall.emission = {emitted, emitted, emitted};
  add_sphere(scene, {0, 0, 0}, 1, add_material(scene, wall));
  scene.cameras.push_back(perspective_camera({0.2f, -0.1f, 0.3f}, {0, 0, -1}, {0, 1, 0}, 90));
  RenderResult r = render_finite(scene, path_options(image_size, 64, depth));
  double sum = 0;
  for (const FilmPixel& p : r.film.pixels) sum += mean(pixel_mean(p));
  return sum / double(r.film.pixels.size());
}

// Le (1 + kd + ... + kd^depth): what a path of `depth` gathering vertices collects.
double furnace_series(float kd, float emitted, int depth) {
  double series = 0;
  for (int k = 0; k <= depth; ++k) series += emitted * std::pow(kd, k);
  return series;
}

// The mean over 256 pixels x 64 samples; Russian roulette from depth 3 adds the only noise.
constexpr double furnace_relative_tolerance = 0.01;

}  // namespace

TEST_CASE("enclosure: inside a closed sphere of kd 0.5 emitting Le, the path tracer never returns more than Le / (1 - kd)") {
  constexpr float kd = 0.5f, emitted = 1;
  for (int depth : {1, 3, 8}) {
    CAPTURE(depth);
    double m = furnace_mean(kd, emitted, depth);
    CHECK(m >= emitted);  // the wall seen directly
    CHECK(m <= furnace_series(kd, emitted, depth) * (1 + furnace_relative_tolerance));
    CHECK(m <= emitted / (1 - kd));
  }
}

TEST_CASE("enclosure: inside a closed sphere of kd 0.5 emitting Le, the path tracer returns Le (1 + kd + ... + kd^D)") {
  constexpr float kd = 0.5f, emitted = 1;
  for (int depth : {1, 3, 8}) {
    CAPTURE(depth);
    CHECK(furnace_mean(kd, emitted, depth) == doctest::Approx(furnace_series(kd, emitted, depth)).epsilon(furnace_relative_tolerance));
  }
}
