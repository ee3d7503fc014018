// --indirect-paths: a camera sample's path branches at its first hit into several sub-paths
// (integrators/path.cpp, PathState). The first hit's own light must be counted once, the
// sub-paths must sample bounces of their own, and the image must converge to the one a single
// path per camera sample gives.
#include <doctest/doctest.h>

#include <cmath>

#include "load_scene.h"
#include "render/settings_hash.h"
#include "support/film_measures.h"
#include "support/scene_builders.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// A room open towards the camera, lit by one point light: the first hit's direct light has no
// noise of its own, so what --indirect-paths changes is the bounce alone.
SceneDesc point_lit_room() {
  SceneDesc scene;
  int white = add_diffuse(scene, {0.7f, 0.7f, 0.7f}), red = add_diffuse(scene, {0.7f, 0.1f, 0.1f});
  add_quad(scene, {-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}, white);  // floor
  add_quad(scene, {-2, 4, -2}, {2, 4, -2}, {2, 4, 2}, {-2, 4, 2}, white);  // ceiling
  add_quad(scene, {-2, 0, -2}, {2, 0, -2}, {2, 4, -2}, {-2, 4, -2}, white);  // back
  add_quad(scene, {-2, 0, -2}, {-2, 4, -2}, {-2, 4, 2}, {-2, 0, 2}, red);    // left
  add_quad(scene, {2, 0, -2}, {2, 0, 2}, {2, 4, 2}, {2, 4, -2}, white);      // right
  scene.lights.push_back(point_light({0, 3.5f, 0}, {6, 6, 6}));
  scene.cameras.push_back(perspective_camera({0, 2, 6}, {0, 0, -1}, {0, 1, 0}, 45));
  return scene;
}

RenderOptions small_render(int spp, int indirect_paths, int max_depth) {
  RenderOptions o;
  o.width = 24, o.height = 24, o.spp = spp, o.mode = RenderMode::path, o.max_depth = max_depth;
  o.indirect_paths = indirect_paths;
  return o;
}

}  // namespace

TEST_CASE("indirect paths: the first hit's direct light is counted once") {
  // Direct light only (depth 1): the extra sub-paths' bounces find no emitter, so the image is
  // the single path's to the bit, while they still trace their bounces.
  SceneDesc scene = point_lit_room();
  RenderResult one = render_scene(scene, small_render(4, 1, 1));
  RenderResult four = render_scene(scene, small_render(4, 4, 1));
  CHECK(four.settings.indirect_paths == 4);
  REQUIRE(one.film.pixels.size() == four.film.pixels.size());
  int differing = 0;
  for (size_t i = 0; i < one.film.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) differing += !(one.film.pixels[i].sum[c] == four.film.pixels[i].sum[c]);
  CHECK(differing == 0);
  CHECK(mean_luminance(one.film) > 0.01);
  CHECK(four.stats.rays.camera == one.stats.rays.camera);
  CHECK(four.stats.rays.shadow == one.stats.rays.shadow);  // one light sample per camera hit
  CHECK(four.stats.rays.indirect == 4 * one.stats.rays.indirect);
}

TEST_CASE("indirect paths: sub-paths sample bounces of their own and converge to the same image") {
  SceneDesc scene = point_lit_room();
  RenderResult reference = render_scene(scene, small_render(256, 1, 8));
  RenderResult single = render_scene(scene, small_render(4, 1, 8));
  RenderResult split = render_scene(scene, small_render(4, 4, 8));
  RenderResult equal_bounces = render_scene(scene, small_render(16, 1, 8));
  // The same light on average (indirect light is most of this room's, so a double-counted or
  // lost first hit, or a wrong 1/4 share, would move the mean by far more than 3%).
  CHECK(std::abs(mean_luminance(split.film) / mean_luminance(reference.film) - 1) < 0.03);
  // Four bounces per camera sample remove noise that four identical ones would not...
  double single_error = rms_difference(single.film, reference.film);
  double split_error = rms_difference(split.film, reference.film);
  double equal_error = rms_difference(equal_bounces.film, reference.film);
  CAPTURE(single_error);
  CAPTURE(split_error);
  CAPTURE(equal_error);
  CHECK(split_error < 0.7 * single_error);
  // ...nearly as much as four times the camera samples, whose bounces they share.
  CHECK(split_error < 1.25 * equal_error);
}

TEST_CASE("indirect paths: with an area light, MIS between the one light sample and the sub-paths' bounces") {
  // The first sub-path's light sample and every sub-path's bounce that hits the lamp (each 1/4)
  // are weighed against each other: the box must stay as bright as with one path (the lamp's
  // edges, seen directly, are most of the mean's noise: 32 camera samples).
  SceneDesc scene = load_scene(source_path("assets/cornell.gltf").string());
  RenderOptions reference = small_render(256, 1, 8), split = small_render(32, 4, 8);
  double expected = mean_luminance(render_scene(scene, reference).film);
  CHECK(std::abs(mean_luminance(render_scene(scene, split).film) / expected - 1) < 0.015);
}

TEST_CASE("indirect paths: a render with sub-paths is another render to merge and to Whitted") {
  SceneDesc scene = point_lit_room();
  RenderOptions one = small_render(4, 1, 8), two = small_render(4, 2, 8);
  RenderResult a = render_scene(scene, one), b = render_scene(scene, two);
  CHECK(settings_hash(a.settings, one) != settings_hash(b.settings, two));
  RenderOptions whitted = small_render(4, 2, 8);
  whitted.mode = RenderMode::whitted;
  CHECK_THROWS_WITH_AS(render_scene(scene, whitted), doctest::Contains("--indirect-paths"), std::invalid_argument);
}
