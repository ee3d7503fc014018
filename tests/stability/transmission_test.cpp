// Reflection and transmission in Whitted mode: total internal reflection sends the whole
// transmitted share into the reflection, ior 1 passes rays straight through, and kr = 1 or
// kt = 1 never gives back more than the surface sees (docs/stability.md, case 3).
#include <doctest/doctest.h>

#include <cmath>

#include "stability/film_checks.h"
#include "stability/scene_pieces.h"

using namespace radiant;
using namespace radiant::test;

namespace {

const color3 below_emission = {0.25f, 0.5f, 1};
const color3 above_emission = {1, 0.5f, 0.25f};
// Whitted sums a handful of float products per pixel: agreement to float rounding.
constexpr float exact_relative_tolerance = 1e-5f;

int add_emitter(SceneDesc& scene, color3 emission) {
  MaterialDesc m;
  m.emission = emission;
  return add_material(scene, m);
}

int add_glass(SceneDesc& scene, float kt, float kr, float ior) {
  MaterialDesc m;
  m.kt = {kt, kt, kt};
  m.kr = {kr, kr, kr};
  m.ior = ior;
  return add_material(scene, m);
}

// A horizontal emissive quad at height y, 100 units wide, facing `up` or down.
void add_emissive_floor(SceneDesc& scene, float y, color3 emission) {
  int m = add_emitter(scene, emission);
  add_quad(scene, {-50, y, -50}, {-50, y, 50}, {50, y, 50}, {50, y, -50}, m);
}

void check_close(color3 got, color3 expected) {
  for (int c = 0; c < 3; ++c) CHECK(got[c] == doctest::Approx(expected[c]).epsilon(exact_relative_tolerance));
}

// Every pixel of a tiny orthographic view looking along `forward` from `position`.
color3 ortho_view(SceneDesc scene, vec3 position, vec3 forward, vec3 up) {
  scene.cameras = {ortho_camera(position, forward, up, 0.01f)};
  RenderResult r = render_finite(scene, whitted_options(4));
  color3 first = pixel_mean(r.film.pixels[0]);
  for (const FilmPixel& p : r.film.pixels) check_close(pixel_mean(p), first);
  return first;
}

}  // namespace

TEST_CASE("transmission: inside glass (ior 1.5) beyond the critical angle all of kt reflects, below it kt transmits") {
  // The glass fills y < 0 under the plane; emitters at y = -1 (inside) and y = 1 (outside).
  for (auto coefficients : {std::pair{1.0f, 0.0f}, {0.6f, 0.0f}, {0.6f, 0.3f}}) {
    float kt = coefficients.first, kr = coefficients.second;  // clang 14 cannot capture a structured binding in CAPTURE
    CAPTURE(kt);
    CAPTURE(kr);
    SceneDesc scene;
    add_plane(scene, {0, 0, 0}, {0, 1, 0}, add_glass(scene, kt, kr, 1.5f));
    add_emissive_floor(scene, -1, below_emission);
    add_emissive_floor(scene, 1, above_emission);
    // 60 degrees from the normal, beyond asin(1/1.5) = 41.8: the reflection gets kr + kt.
    float s60 = std::sin(pi / 3), c60 = std::cos(pi / 3);
    check_close(ortho_view(scene, {0, -0.5f, 0}, {s60, c60, 0}, {0, 0, 1}), below_emission * (kr + kt));
    // 30 degrees: refracted out at asin(0.75) to the upper emitter, kr reflected to the lower.
    float s30 = std::sin(pi / 6), c30 = std::cos(pi / 6);
    check_close(ortho_view(scene, {0, -0.5f, 0}, {s30, c30, 0}, {0, 0, 1}), above_emission * kt + below_emission * kr);
  }
}

TEST_CASE("transmission: inside a glass sphere a ray beyond the critical angle stays inside and below it leaves") {
  SceneDesc scene;
  add_sphere(scene, {0, 0, 0}, 1, add_glass(scene, 1, 0, 1.5f));
  // From (0, 0.8, 0) along +x the ray meets the sphere at (0.6, 0.8) with sin(incidence) = 0.8
  // > 1/1.5 and reflects along (0.28, -0.96); a small emitter sits on that chord.
  add_sphere(scene, {0.768f, 0.224f, 0}, 0.05f, add_emitter(scene, below_emission));
  scene.environment.color = {1, 1, 1};
  check_close(ortho_view(scene, {0, 0.8f, 0}, {1, 0, 0}, {0, 1, 0}), below_emission);
  // At height 0.3, sin(incidence) = 0.3: out through the sphere into the white background.
  check_close(ortho_view(scene, {0, 0.3f, 0}, {1, 0, 0}, {0, 1, 0}), {1, 1, 1});
}

TEST_CASE("transmission: a kt surface with ior exactly 1 passes rays straight: the image behind is kt times the image without it") {
  auto lit_plane = [] {
    SceneDesc scene;
    add_plane(scene, {0, 0, 0}, {0, 1, 0}, add_diffuse(scene, {0.8f, 0.6f, 0.4f}));
    scene.lights.push_back(point_light({0.5f, 1.5f, 0.3f}, {5, 5, 5}));  // below the glass
    scene.cameras.push_back(perspective_camera({0, 3, 2}, {0, -3, -2}, {0, 1, 0}, 40));
    return scene;
  };
  RenderResult bare = render_finite(lit_plane(), whitted_options(16));
  SUBCASE("a quad: one interface") {
    SceneDesc scene = lit_plane();
    add_quad(scene, {-10, 2, -10}, {-10, 2, 10}, {10, 2, 10}, {10, 2, -10}, add_glass(scene, 0.6f, 0, 1));
    RenderResult r = render_finite(scene, whitted_options(16));
    for (size_t i = 0; i < r.film.pixels.size(); ++i)
      check_close(pixel_mean(r.film.pixels[i]), pixel_mean(bare.film.pixels[i]) * 0.6f);
  }
  SUBCASE("a sphere filling the view: two interfaces") {
    SceneDesc scene = lit_plane();
    add_sphere(scene, {0, 3, 2}, 0.5f, add_glass(scene, 0.6f, 0, 1));  // around the camera
    RenderResult r = render_finite(scene, whitted_options(16));
    for (size_t i = 0; i < r.film.pixels.size(); ++i)
      check_close(pixel_mean(r.film.pixels[i]), pixel_mean(bare.film.pixels[i]) * 0.6f);
  }
}

TEST_CASE("transmission: a kr = 1 mirror and a kt = 1 pane give back exactly what they see, never more") {
  SUBCASE("mirror") {
    SceneDesc scene;
    MaterialDesc mirror;
    mirror.kr = {1, 1, 1};
    add_plane(scene, {0, 0, 0}, {0, 1, 0}, add_material(scene, mirror));
    add_emissive_floor(scene, 2, above_emission);
    check_close(ortho_view(scene, {0, 1, 0}, normalize(vec3{0.3f, -1, 0.2f}), {0, 0, 1}), above_emission);
  }
  SUBCASE("pane of glass, ior 1.5, seen at 50 degrees") {
    SceneDesc scene;
    add_quad(scene, {-50, 0, -50}, {-50, 0, 50}, {50, 0, 50}, {50, 0, -50}, add_glass(scene, 1, 0, 1.5f));
    add_emissive_floor(scene, -1, below_emission);
    float s = std::sin(50 * pi / 180), c = std::cos(50 * pi / 180);
    check_close(ortho_view(scene, {0, 1, 0}, {s, -c, 0}, {0, 0, 1}), below_emission);
  }
}
