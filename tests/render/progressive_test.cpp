// Progressive rendering (RenderOptions::on_pass, used by `radiant session`): passes that double,
// and a final film equal to the one-pass render's.
#include <doctest/doctest.h>

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
