// Touching, coplanar and very thin objects: where two surfaces meet, the shadow rays of one must
// not catch on the other, and light must not slip through a wall 1e-4 thick
// (docs/stability.md, case 3).
#include <doctest/doctest.h>

#include "stability/film_checks.h"
#include "stability/reference_scene.h"
#include "stability/scene_pieces.h"

using namespace radiant;
using namespace radiant::test;

namespace {

constexpr int image_size = 32;
constexpr float grey = 0.5f;
constexpr float ambient_light = 0.1f;
// Near the origin the render is good to float rounding; the reference's own float arithmetic
// (sphere hits, cosines) adds a few 1e-6 on top.
constexpr float exact_relative_tolerance = 5e-5f;

// Every surface grey (kd = ka = 0.5) under one point light and an ambient light.
SceneDesc grey_scene(vec3 light, float intensity, float ambient, int& material) {
  SceneDesc scene;
  MaterialDesc m;
  m.kd = {grey, grey, grey};
  m.ka = {grey, grey, grey};
  material = add_material(scene, m);
  scene.lights.push_back(point_light(light, {intensity, intensity, intensity}));
  LightDesc a;
  a.kind = LightKind::ambient;
  a.intensity = {ambient, ambient, ambient};
  scene.lights.push_back(a);
  return scene;
}

ReferenceScene grey_reference(vec3 light, float intensity, float ambient) {
  ReferenceScene r;
  r.light = light;
  r.intensity = intensity;
  r.kd = grey;
  r.ambient = grey * ambient;
  return r;
}

void check_exact(const ReferenceCheck& c, int min_lit, int min_shadowed) {
  CHECK(c.lit >= min_lit);
  CHECK(c.shadowed >= min_shadowed);
  CHECK(c.dark_speckles == 0);
  CHECK(c.light_leaks == 0);
  CHECK(c.max_lit_relative_error <= exact_relative_tolerance);
}

}  // namespace

TEST_CASE("contact: spheres touching each other and the plane are lit exactly up to their contact points") {
  const vec3 light = {2, 8, 3};
  int m;
  SceneDesc scene = grey_scene(light, 60, ambient_light, m);
  ReferenceScene reference = grey_reference(light, 60, ambient_light);
  // Two side by side on the plane, a third stacked on the first: five contact points.
  for (vec3 center : {vec3{-1, 1, 0}, vec3{1, 1, 0}, vec3{-1, 3, 0}}) {
    add_sphere(scene, center, 1, m);
    reference.spheres.push_back({center, 1});
  }
  add_plane(scene, {0, 0, 0}, {0, 1, 0}, m);
  scene.cameras.push_back(perspective_camera({0.5f, 2, 7}, vec3{0, 1.5f, 0} - vec3{0.5f, 2, 7}, {0, 1, 0}, 50));
  RenderResult r = render_finite(scene, whitted_options(image_size));
  check_exact(check_against_reference(r.film, scene.cameras[0], reference, 0.01f), 300, 100);
}

TEST_CASE("contact: a box resting on a plane and coplanar overlapping quads on it show no acne, at the origin and 1e5 away") {
  const vec3 light = {-1, 3, -2.5f};
  for (float offset : {0.0f, 1e5f}) {
    CAPTURE(offset);
    vec3 shift = {offset, offset, offset};
    int m;
    SceneDesc scene = grey_scene(light + shift, 30, ambient_light, m);
    add_plane(scene, shift, {0, 1, 0}, m);
    add_box(scene, vec3{0.5f, 0, -0.5f} + shift, {1, 1, 1}, m);
    // Two quads lying exactly in the plane, overlapping each other and the box's footprint.
    add_quad(scene, vec3{-2, 0, -1} + shift, vec3{-2, 0, 1} + shift, vec3{1, 0, 1} + shift, vec3{1, 0, -1} + shift, m);
    add_quad(scene, vec3{-1, 0, 0} + shift, vec3{-1, 0, 2} + shift, vec3{2, 0, 2} + shift, vec3{2, 0, 0} + shift, m);
    vec3 eye = {0, 3, 5};
    scene.cameras.push_back(perspective_camera(eye + shift, vec3{0.5f, 0, 0} - eye, {0, 1, 0}, 50));
    RenderResult r = render_finite(scene, whitted_options(image_size));
    ReferenceScene reference = grey_reference(light, 30, ambient_light);
    reference.boxes.push_back({{0.5f, 0, -0.5f}, {1.5f, 1, 0.5f}});
    CameraDesc unit_camera = perspective_camera(eye, vec3{0.5f, 0, 0} - eye, {0, 1, 0}, 50);
    ReferenceCheck c = check_against_reference(r.film, unit_camera, reference, 0.02f);
    CHECK(c.lit >= 500);
    CHECK(c.shadowed >= 50);
    CHECK(c.dark_speckles == 0);
    CHECK(c.light_leaks == 0);
    // At 1e5 hit points sit on a 1/128 grid (see the translation case for the derivation).
    CHECK(c.max_lit_relative_error <= (offset == 0 ? exact_relative_tolerance : 0.02f));
  }
}

TEST_CASE("contact: a box 1e-4 thick lit from above is lit exactly on top, black underneath, and shadows the plane") {
  const vec3 light = {0.2f, 3, 0.1f};
  int m;
  SceneDesc scene = grey_scene(light, 20, 0, m);  // no ambient: the dark side must be exactly 0
  add_plane(scene, {0, 0, 0}, {0, 1, 0}, m);
  add_box(scene, {-1, 0.5f, -1}, {2, 1e-4f, 2}, m);
  ReferenceScene reference = grey_reference(light, 20, 0);
  reference.boxes.push_back({{-1, 0.5f, -1}, {1, 0.5001f, 1}});
  // The margin must stay below half the thickness, or the reference cannot see the box at all.
  constexpr float thin_margin = 2e-5f;
  SUBCASE("seen from above: the top face") {
    CameraDesc above = ortho_camera({0, 2, 0}, {0, -1, 0}, {0, 0, -1}, 1.8f);
    scene.cameras.push_back(above);
    RenderResult r = render_finite(scene, whitted_options(image_size));
    check_exact(check_against_reference(r.film, above, reference, thin_margin), image_size * image_size, 0);
  }
  SUBCASE("seen from below the box: its underside and the plane in its shadow") {
    vec3 eye = {0, 0.25f, 3};
    CameraDesc low = perspective_camera(eye, vec3{0, 0.3f, 0} - eye, {0, 1, 0}, 40);
    scene.cameras.push_back(low);
    RenderResult r = render_finite(scene, whitted_options(image_size));
    ReferenceCheck c = check_against_reference(r.film, low, reference, thin_margin);
    check_exact(c, 0, 150);
    size_t black = 0;
    for (const FilmPixel& p : r.film.pixels) black += is_black(pixel_mean(p));
    CHECK(black >= 300);
  }
}
