// The sample clamps (--clamp-direct, --clamp-indirect): a sample's light is bounded by them, and
// they are off by default.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "integrators/sample_clamp.h"
#include "support/film_measures.h"
#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// A small, very bright emitting square above a diffuse floor under a dark sky: direct light from
// an emitter the light samples rarely catch at a grazing angle, and bright bounces.
SceneDesc small_bright_emitter() {
  SceneDesc scene;
  int floor = add_diffuse(scene, {0.8f, 0.8f, 0.8f});
  add_quad(scene, {-3, 0, -3}, {-3, 0, 3}, {3, 0, 3}, {3, 0, -3}, floor);
  add_quad(scene, {-3, 0, -3}, {3, 0, -3}, {3, 3, -3}, {-3, 3, -3}, floor);
  MaterialDesc lamp;
  lamp.emission = {200000, 200000, 200000};
  int lamp_material = add_material(scene, lamp);
  add_quad(scene, {-0.05f, 2, -0.05f}, {0.05f, 2, -0.05f}, {0.05f, 2, 0.05f}, {-0.05f, 2, 0.05f}, lamp_material);
  scene.cameras.push_back(perspective_camera({0, 1.5f, 5}, {0, -0.2f, -1}, {0, 1, 0}, 50));
  return scene;
}

// The largest sum of channels of any one-sample pixel.
float largest_sample(const Film& film) {
  float largest = 0;
  for (const FilmPixel& p : film.pixels) {
    color3 v = pixel_mean(p);
    largest = std::max(largest, std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z));
  }
  return largest;
}

RenderOptions one_sample(int max_depth) {
  RenderOptions o;
  o.width = 40, o.height = 30, o.spp = 1, o.mode = RenderMode::path, o.max_depth = max_depth;
  o.env_color = color3{0.01f, 0.01f, 0.01f};
  return o;
}

}  // namespace

TEST_CASE("sample clamp: a contribution whose channels sum above the limit is scaled down to it, keeping its hue") {
  RenderContext ctx;
  ctx.clamp_direct = 3, ctx.clamp_indirect = 1;
  color3 bright = {4, 2, 0};
  color3 direct = clamp_contribution(ctx, bright, 0);
  CHECK(direct.x == doctest::Approx(2));
  CHECK(direct.y == doctest::Approx(1));
  CHECK(direct.z == 0);
  CHECK(clamp_contribution(ctx, bright, -1).x == doctest::Approx(2));  // what the camera sees is direct
  color3 indirect = clamp_contribution(ctx, bright, 1);
  CHECK(indirect.x + indirect.y + indirect.z == doctest::Approx(1));
  color3 dim = {0.5f, 0.2f, 0.1f};
  CHECK(clamp_contribution(ctx, dim, 2).x == dim.x);
  ctx.clamp_direct = ctx.clamp_indirect = 0;  // off
  CHECK(clamp_contribution(ctx, bright, 0).x == 4);
}

// A sample gathers at most three contributions at its first hit (what the camera sees, the light
// sample, the light its bounce finds) and two at each later vertex (its light sample, the light
// its bounce finds); each is clamped, as in Cycles.
TEST_CASE("sample clamp: a one-sample pixel holds at most 3 direct clamps, and each bounce adds at most 2 indirect clamps") {
  SceneDesc scene = small_bright_emitter();
  RenderResult free_direct = render_scene(scene, one_sample(1));
  REQUIRE(largest_sample(free_direct.film) > 50);  // the lamp seen, and its light on the walls
  RenderOptions o = one_sample(1);
  o.clamp_direct = 2;
  RenderResult direct_clamped = render_scene(scene, o);
  CHECK(largest_sample(direct_clamped.film) <= 3 * 2 * 1.0001f);
  CHECK(mean_luminance(direct_clamped.film) < mean_luminance(free_direct.film));

  RenderResult free_bounce = render_scene(scene, one_sample(2));
  RenderOptions both = one_sample(2);
  both.clamp_direct = 2, both.clamp_indirect = 0.5f;
  CHECK(largest_sample(render_scene(scene, both).film) <= (3 * 2 + 2 * 0.5f) * 1.0001f);
  // The indirect clamp alone leaves the direct light as it was (the same numbers drawn) and
  // bounds what the bounce adds.
  RenderOptions indirect_only = one_sample(2);
  indirect_only.clamp_indirect = 0.5f;
  RenderResult bounce_clamped = render_scene(scene, indirect_only);
  float largest_bounce = 0;
  for (size_t i = 0; i < free_direct.film.pixels.size(); ++i) {
    color3 bounce = pixel_mean(bounce_clamped.film.pixels[i]) - pixel_mean(free_direct.film.pixels[i]);
    largest_bounce = std::max(largest_bounce, std::fabs(bounce.x) + std::fabs(bounce.y) + std::fabs(bounce.z));
  }
  CHECK(largest_bounce <= 2 * 0.5f * 1.001f);
  CHECK(largest_bounce > 0.25f);  // it did clamp something
  CHECK(mean_luminance(bounce_clamped.film) < mean_luminance(free_bounce.film));
}

TEST_CASE("sample clamp: off by default, a clamp above every sample changes no bit") {
  SceneDesc scene = small_bright_emitter();
  RenderOptions o = one_sample(3);
  o.spp = 4;
  RenderResult free = render_scene(scene, o);
  o.clamp_direct = o.clamp_indirect = 1e30f;
  RenderResult high = render_scene(scene, o);
  for (size_t i = 0; i < free.film.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) REQUIRE(free.film.pixels[i].sum[c] == high.film.pixels[i].sum[c]);
}
