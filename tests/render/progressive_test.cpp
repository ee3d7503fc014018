// Progressive rendering: passes over the whole image that double what every pixel holds, taken
// whenever a render may stop early (RenderOptions::on_pass, stop_request, a time limit), a final
// film equal to the one-pass render's, and a stopped render that has a sample in every pixel.
#include <doctest/doctest.h>

#include <atomic>
#include <cstring>
#include <vector>

#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

SceneDesc lit_sphere() {
  SceneDesc scene;
  add_sphere(scene, {0, 0, -3}, 1, add_diffuse(scene, {0.7f, 0.5f, 0.3f}));
  add_plane(scene, {0, -1, 0}, {0, 1, 0}, add_diffuse(scene, {0.5f, 0.5f, 0.5f}));
  scene.lights.push_back(point_light({2, 3, 0}, {20, 20, 20}));
  scene.cameras.push_back(perspective_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60));
  return scene;
}

bool same_film(const Film& a, const Film& b) {
  if (a.pixels.size() != b.pixels.size()) return false;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    if (std::memcmp(a.pixels[i].sum, b.pixels[i].sum, sizeof a.pixels[i].sum) != 0 ||
        a.pixels[i].samples != b.pixels[i].samples)
      return false;
  return true;
}

}  // namespace

TEST_CASE("progressive passes: 1, 2, 4, ... samples, and the final film is the one-pass render's") {
  for (RenderMode mode : {RenderMode::path, RenderMode::whitted}) {
    RenderOptions options;
    options.width = options.height = 16;
    options.spp = 12;
    options.mode = mode;
    RenderResult one_pass = render_scene(lit_sphere(), options);

    std::vector<uint32_t> passes;
    options.on_pass = [&](const Film& film, uint32_t samples) {
      passes.push_back(samples);
      CHECK(film.pixels[0].samples == samples);  // the film holds what the pass says
    };
    RenderResult progressive = render_scene(lit_sphere(), options);
    CHECK(passes == std::vector<uint32_t>{1, 2, 4, 8, 12});
    CHECK(same_film(progressive.film, one_pass.film));
  }
}

TEST_CASE("progressive passes: a stoppable render's film equals the one-pass render's at any spp and batching") {
  std::atomic<int> never{0};
  for (PathBatching batching : {PathBatching::none, PathBatching::camera_rays, PathBatching::all_rays}) {
    CAPTURE(int(batching));
    RenderOptions options;
    options.width = options.height = 20;
    options.spp = 13;  // passes of 1, 1, 2, 4 and a last one of 5
    options.mode = RenderMode::path;
    options.path_batching = batching;
    RenderResult one_pass = render_scene(lit_sphere(), options);
    CHECK(one_pass.stats.passes == 1);
    options.stop_request = &never;
    RenderResult passes = render_scene(lit_sphere(), options);
    CHECK(passes.stats.passes == 5);
    CHECK(passes.stats.samples_reached == 13);
    CHECK(same_film(passes.film, one_pass.film));
  }
}

TEST_CASE("progressive passes: a stop asked before the render still gives every pixel its first sample") {
  std::atomic<int> stop{2};  // as if SIGINT had already arrived
  RenderOptions options;
  options.width = options.height = 24;
  options.spp = 64;
  options.mode = RenderMode::path;
  options.stop_request = &stop;
  RenderResult r = render_scene(lit_sphere(), options);
  CHECK(r.stats.interrupted);
  CHECK(r.stats.passes == 1);
  CHECK(r.stats.samples_reached == 1);
  CHECK(r.stats.min_pixel_samples == 1);
  CHECK(r.stats.max_pixel_samples == 1);

  options.stop_completes_first_pass = false;  // a session's replaced render
  RenderResult dropped = render_scene(lit_sphere(), options);
  CHECK(dropped.stats.interrupted);
  CHECK(dropped.stats.samples == 0);
}

TEST_CASE("progressive passes: a stop during a later pass keeps every pixel at or above the passes before it") {
  std::atomic<int> stop{0};
  RenderOptions options;
  options.width = options.height = 24;
  options.spp = 64;
  options.mode = RenderMode::path;
  options.stop_request = &stop;
  options.on_pass = [&](const Film&, uint32_t samples) {
    if (samples == 4) stop = 2;  // the signal arrives as the pass to 8 starts
  };
  RenderResult r = render_scene(lit_sphere(), options);
  CHECK(r.stats.interrupted);
  CHECK(r.stats.samples_reached == 4);
  CHECK(r.stats.min_pixel_samples == 4);
  CHECK(r.stats.max_pixel_samples <= 8);
}
