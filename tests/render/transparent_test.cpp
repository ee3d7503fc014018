// --transparent: alpha is the coverage of geometry by camera rays, and the background they would
// see is black while the environment still lights the scene.
#include <doctest/doctest.h>

#include <cmath>

#include "integrators/render_context.h"
#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

constexpr int image_size = 16;
constexpr float view_height = 4, sphere_radius = 1.3f;

// A diffuse sphere at the origin under a white sky, seen by an orthographic camera covering
// [-2, 2]^2: its silhouette is the disc of radius 1.3, whose edge crosses pixels at every
// fraction.
SceneDesc sphere_under_sky() {
  SceneDesc scene;
  add_sphere(scene, {0, 0, 0}, sphere_radius, add_diffuse(scene, {0.5f, 0.5f, 0.5f}));
  scene.cameras.push_back(ortho_camera({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, view_height));
  scene.environment.color = {1, 1, 1};
  return scene;
}

RenderOptions sphere_options(bool transparent) {
  RenderOptions o;
  o.width = image_size, o.height = image_size;
  o.spp = 256;
  o.mode = RenderMode::path;
  o.max_depth = 2;
  o.transparent = transparent;
  return o;
}

// The fraction of pixel (x, y) inside the disc, by a 256 x 256 midpoint rule (the disc is
// symmetric, so which way the image axes run does not matter).
double disc_coverage(int x, int y) {
  constexpr int n = 256;
  double pixel = double(view_height) / image_size, inside = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      double wx = -view_height / 2 + pixel * (x + (i + 0.5) / n), wy = -view_height / 2 + pixel * (y + (j + 0.5) / n);
      inside += wx * wx + wy * wy < double(sphere_radius) * sphere_radius;
    }
  return inside / (n * n);
}

}  // namespace

TEST_CASE("transparent: alpha is 1 inside a sphere, 0 outside, and its analytic coverage on the silhouette's pixels") {
  RenderResult r = render_scene(sphere_under_sky(), sphere_options(true));
  REQUIRE(r.film.alpha.size() == r.film.pixels.size());
  int edge_pixels = 0;
  for (int y = 0; y < image_size; ++y)
    for (int x = 0; x < image_size; ++x) {
      CAPTURE(x);
      CAPTURE(y);
      double expected = disc_coverage(x, y);
      float alpha = pixel_alpha(r.film, size_t(y) * image_size + x);
      if (expected == 1 || expected == 0) {
        CHECK(alpha == float(expected));  // every sample agrees
      } else {
        ++edge_pixels;
        CHECK(std::abs(alpha - expected) < 0.02);
      }
    }
  CHECK(edge_pixels >= 20);
}

TEST_CASE("transparent: camera rays that miss see black, but the sky still lights the sphere as in an opaque render") {
  RenderResult transparent = render_scene(sphere_under_sky(), sphere_options(true));
  RenderResult opaque = render_scene(sphere_under_sky(), sphere_options(false));
  CHECK(opaque.film.alpha.empty());
  // A corner sees the sky in the opaque render and nothing in the transparent one.
  CHECK(pixel_mean(opaque.film.at(0, 0)).x == doctest::Approx(1));
  CHECK(pixel_mean(transparent.film.at(0, 0)).x == 0);
  // The centre's paths all start on the sphere: the sky they reach after a bounce is the same.
  color3 lit = pixel_mean(transparent.film.at(image_size / 2, image_size / 2));
  CHECK(lit.x > 0.2f);
  CHECK(lit == pixel_mean(opaque.film.at(image_size / 2, image_size / 2)));
}

TEST_CASE("transparent: the image gets an A channel after B, its color associated (premultiplied) by it") {
  RenderResult r = render_scene(sphere_under_sky(), sphere_options(true));
  OutputImage image = film_to_image(r.film, {"depth"});
  REQUIRE(image.channels == std::vector<std::string>{"R", "G", "B", "A", "Z"});
  // An edge pixel: its color is the mean over all samples, the background ones adding black.
  size_t edge = 0;
  for (size_t i = 0; i < r.film.pixels.size(); ++i)
    if (pixel_alpha(r.film, i) > 0.3f && pixel_alpha(r.film, i) < 0.7f) edge = i;
  REQUIRE(edge > 0);
  CHECK(image.pixels[edge * 5 + 3] == pixel_alpha(r.film, edge));
  CHECK(image.pixels[edge * 5 + 0] == pixel_mean(r.film.pixels[edge]).x);
}

TEST_CASE("transparent: Whitted's partly opaque surface covers its pixel by its opacity") {
  SceneDesc scene;
  MaterialDesc veil;
  veil.kd = {1, 1, 1};
  veil.alpha = 0.25f;
  veil.alpha_mode = AlphaMode::blend;
  add_quad(scene, {-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}, add_material(scene, veil));
  scene.cameras.push_back(ortho_camera({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 2));
  RenderOptions o;
  o.width = 4, o.height = 4, o.spp = 1;
  o.mode = RenderMode::whitted;
  o.transparent = true;
  RenderResult r = render_scene(scene, o);
  for (size_t i = 0; i < r.film.pixels.size(); ++i) CHECK(pixel_alpha(r.film, i) == doctest::Approx(0.25));
}

TEST_CASE("see-through: both integrators see through at most 256 partly opaque surfaces, then black") {
  // Whitted recursed once per see-through step with no bound: the OBJ fuzzer's stack of blended
  // triangles overflowed the stack (tests/fuzz/regressions/obj/crash-whitted-see-through-recursion.obj).
  for (RenderMode mode : {RenderMode::whitted, RenderMode::path}) {
    for (int layers : {max_see_through_steps - 1, max_see_through_steps}) {
      CAPTURE(int(mode));
      CAPTURE(layers);
      SceneDesc scene;
      MaterialDesc veil;  // black and nearly clear: it only lets the white sky through
      veil.kd = {0, 0, 0};
      veil.alpha = 1e-6f;
      veil.alpha_mode = AlphaMode::blend;
      int m = add_material(scene, veil);
      for (int i = 0; i < layers; ++i) {
        float z = -0.01f * float(i);
        add_quad(scene, {-5, -5, z}, {5, -5, z}, {5, 5, z}, {-5, 5, z}, m);
      }
      scene.cameras.push_back(ortho_camera({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 2));
      scene.environment.color = {1, 1, 1};
      RenderOptions o;
      o.width = 2, o.height = 2, o.spp = 1;
      o.mode = mode;
      RenderResult r = render_scene(scene, o);
      float seen = pixel_mean(r.film.pixels[0]).x;
      if (layers < max_see_through_steps) CHECK(seen == doctest::Approx(1).epsilon(1e-3));
      else CHECK(seen < 1e-3f);
    }
  }
}
