// A render whose camera rays are traced a tile at a time as Embree packets is the render that
// traces each camera ray alone (RenderOptions::coherent_camera_rays = false, the reference),
// bit for bit: radiance, AOVs and coverage, for both integrators, with a lens, a filter with
// negative lobes and a window.
#include <doctest/doctest.h>

#include "load_scene.h"
#include "support/scene_builders.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

bool films_identical(const Film& a, const Film& b) {
  if (a.pixels.size() != b.pixels.size() || a.aovs.size() != b.aovs.size() || a.alpha.size() != b.alpha.size())
    return false;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const FilmPixel &p = a.pixels[i], &q = b.pixels[i];
    if (p.samples != q.samples || p.negative_samples != q.negative_samples) return false;
    for (int c = 0; c < 3; ++c)
      if (!(p.sum[c] == q.sum[c]) || !(p.sum_squares[c] == q.sum_squares[c])) return false;
  }
  for (size_t i = 0; i < a.aovs.size(); ++i) {
    const FilmAovs &p = a.aovs[i], &q = b.aovs[i];
    if (!(p.depth == q.depth)) return false;
    for (int c = 0; c < 3; ++c)
      if (!(p.albedo[c] == q.albedo[c]) || !(p.normal[c] == q.normal[c])) return false;
  }
  for (size_t i = 0; i < a.alpha.size(); ++i)
    if (!(a.alpha[i] == b.alpha[i])) return false;
  return true;
}

// Both ways of tracing camera rays; checks that the packets were used and the images agree.
void require_same_render(const SceneDesc& scene, RenderOptions o) {
  o.coherent_camera_rays = false;
  RenderResult alone = render_scene(scene, o);
  o.coherent_camera_rays = true;
  RenderResult together = render_scene(scene, o);
  CHECK(together.stats.rays.camera == alone.stats.rays.camera);
  CHECK(together.stats.rays.total() == alone.stats.rays.total());
  CHECK(films_identical(together.film, alone.film));
}

}  // namespace

TEST_CASE("coherent camera rays: the glTF Cornell box renders the same with packets, path and Whitted") {
  SceneDesc scene = load_scene(source_path("assets/cornell.gltf").string());
  for (RenderMode mode : {RenderMode::path, RenderMode::whitted}) {
    RenderOptions o;
    o.width = 37, o.height = 29, o.spp = 3, o.mode = mode;  // tiles cut short at the edges
    o.aovs = {"albedo", "normal", "depth"};
    CAPTURE(int(mode));
    require_same_render(scene, o);
  }
}

TEST_CASE("coherent camera rays: a lens, Mitchell's negative lobes, a window and a transparent film change nothing") {
  SceneDesc scene = load_scene(source_path("assets/cornell.gltf").string());
  REQUIRE(!scene.cameras.empty());
  scene.cameras[0].lens_radius = 0.01f;
  scene.cameras[0].focus_distance = 1;
  RenderOptions o;
  o.width = 40, o.height = 40, o.spp = 4, o.mode = RenderMode::path;
  o.filter = PixelFilterKind::mitchell;
  o.crop = PixelWindow{5, 3, 33, 38};
  o.transparent = true;
  require_same_render(scene, o);
}
