// The path tracer against scenes whose exact answer is known.
#include <doctest/doctest.h>

#include <cmath>

#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

RenderOptions path_options(int size, int spp) {
  RenderOptions o;
  o.width = size;
  o.height = size;
  o.spp = spp;
  o.mode = RenderMode::path;
  return o;
}

double film_mean(const Film& film, int channel) {
  double sum = 0;
  for (const FilmPixel& p : film.pixels) sum += pixel_mean(p)[channel];
  return sum / double(film.pixels.size());
}

}  // namespace

TEST_CASE("path: white furnace — a diffuse sphere of albedo 1 under a uniform environment of 1 shows 1.0") {
  SceneDesc scene;
  add_sphere(scene, {0, 0, 0}, 1, add_diffuse(scene, {1, 1, 1}));
  scene.cameras.push_back(perspective_camera({0, 0, 4}, {0, 0, -1}, {0, 1, 0}, 30));
  RenderOptions o = path_options(16, 64);
  o.env_color = color3{1, 1, 1};
  o.max_depth = 64;
  RenderResult r = render_scene(scene, o);
  for (const FilmPixel& p : r.film.pixels) {
    color3 v = pixel_mean(p);
    REQUIRE(v.x == doctest::Approx(1.0).epsilon(0.01));
  }
}

TEST_CASE("path: inside a closed diffuse sphere (albedo 0.5) lit by a point light of intensity pi at its centre") {
  SceneDesc scene;
  add_sphere(scene, {0, 0, 0}, 1, add_diffuse(scene, {0.5f, 0.5f, 0.5f}));
  scene.lights.push_back(point_light({0, 0, 0}, {pi, pi, pi}));
  scene.cameras.push_back(perspective_camera({0.1f, 0.2f, 0.3f}, {0, 0, -1}, {0, 1, 0}, 60));
  SUBCASE("unlimited depth converges to 1.0") {
    RenderOptions o = path_options(16, 256);
    o.max_depth = 1000;
    CHECK(film_mean(render_scene(scene, o).film, 1) == doctest::Approx(1.0).epsilon(0.025));
  }
  SUBCASE("--max-depth 1 gives the direct light only, 0.5") {
    RenderOptions o = path_options(16, 16);
    o.max_depth = 1;
    CHECK(film_mean(render_scene(scene, o).film, 1) == doctest::Approx(0.5).epsilon(0.025));
  }
}

TEST_CASE("path: a Lambertian plane under a point light matches rho/pi * I * cos / d^2 per pixel") {
  SceneDesc scene;
  add_plane(scene, {0, 0, 0}, {0, 1, 0}, add_diffuse(scene, {0.7f, 0.6f, 0.5f}));
  vec3 light = {0.4f, 1.2f, 0.1f};
  scene.lights.push_back(point_light(light, {3, 3, 3}));
  scene.cameras.push_back(ortho_camera({0, 5, 0}, {0, -1, 0}, {0, 0, -1}, 4));
  RenderOptions o = path_options(8, 1);
  o.sampler = SamplerKind::jittered;  // one sample through each pixel centre
  RenderResult r = render_scene(scene, o);
  for (auto [x, y] : {std::pair{0, 0}, {2, 6}, {4, 4}, {7, 3}}) {
    vec3 p = {-2 + 0.5f * (x + 0.5f), 0, -(2 - 0.5f * (y + 0.5f))};
    vec3 to_light = light - p;
    float d = length(to_light);
    float expected = 0.7f / pi * 3 * (to_light.y / d) / (d * d);
    CHECK(pixel_mean(r.film.at(x, y)).x == doctest::Approx(expected).epsilon(1e-4));
  }
}

TEST_CASE("path: an emissive quad of known radiance seen directly shows that radiance") {
  SceneDesc scene;
  MaterialDesc emitter;
  emitter.emission = {2.5f, 1.5f, 0.5f};
  emitter.double_sided = false;
  add_quad(scene, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, add_material(scene, emitter));
  scene.cameras.push_back(perspective_camera({0, 0, 3}, {0, 0, -1}, {0, 1, 0}, 20));
  RenderResult r = render_scene(scene, path_options(8, 4));
  color3 centre = pixel_mean(r.film.at(4, 4));
  CHECK(centre.x == doctest::Approx(2.5));
  CHECK(centre.y == doctest::Approx(1.5));
  CHECK(centre.z == doctest::Approx(0.5));
}

TEST_CASE("path: naive and path converge to the same image within Monte Carlo error") {
  SceneDesc scene;
  add_plane(scene, {0, 0, 0}, {0, 1, 0}, add_diffuse(scene, {0.6f, 0.6f, 0.6f}));
  add_sphere(scene, {0, 0.5f, 0}, 0.5f, add_diffuse(scene, {0.8f, 0.3f, 0.3f}));
  MaterialDesc emitter;
  emitter.emission = {6, 6, 6};
  add_sphere(scene, {0.8f, 1.6f, 0.5f}, 0.3f, add_material(scene, emitter));
  scene.cameras.push_back(perspective_camera({0, 1, 3}, normalize(vec3{0, -0.3f, -1}), {0, 1, 0}, 45));
  // Enough samples that per-pixel errors are near Gaussian for the 4.5-sigma test (naive paths
  // find the small light rarely, so its estimate needs four times as many).
  RenderOptions o = path_options(12, 1024);
  o.max_depth = 4;
  RenderResult path = render_scene(scene, o);
  o.mode = RenderMode::naive;
  o.spp = 4096;
  RenderResult naive = render_scene(scene, o);
  // Per pixel: |a - b| within 4.5 combined standard errors for all but a few pixels.
  int outliers = 0;
  for (size_t i = 0; i < path.film.pixels.size(); ++i) {
    color3 a = pixel_mean(path.film.pixels[i]), b = pixel_mean(naive.film.pixels[i]);
    color3 va = pixel_mean_variance(path.film.pixels[i]), vb = pixel_mean_variance(naive.film.pixels[i]);
    float sigma = std::sqrt(va.x + vb.x) + 1e-4f;
    outliers += std::abs(a.x - b.x) > 4.5f * sigma;
  }
  CHECK(outliers <= 2);
  CHECK(film_mean(path.film, 0) == doctest::Approx(film_mean(naive.film, 0)).epsilon(0.02));
}

TEST_CASE("render: --threads never changes the image (same samples, same sums, same order)") {
  SceneDesc scene;
  add_plane(scene, {0, 0, 0}, {0, 1, 0}, add_diffuse(scene, {0.6f, 0.6f, 0.6f}));
  add_sphere(scene, {0, 0.5f, 0}, 0.5f, add_diffuse(scene, {0.8f, 0.3f, 0.3f}));
  scene.lights.push_back(point_light({1, 3, 1}, {10, 10, 10}));
  scene.cameras.push_back(perspective_camera({0, 1, 3}, normalize(vec3{0, -0.3f, -1}), {0, 1, 0}, 45));
  for (RenderMode mode : {RenderMode::path, RenderMode::whitted}) {
    RenderOptions o = path_options(24, 8);
    o.mode = mode;
    o.threads = 1;
    RenderResult one = render_scene(scene, o);
    o.threads = 2;
    RenderResult two = render_scene(scene, o);
    bool identical = true;
    for (size_t i = 0; i < one.film.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c) identical &= one.film.pixels[i].sum[c] == two.film.pixels[i].sum[c];
    CHECK(identical);
  }
}
