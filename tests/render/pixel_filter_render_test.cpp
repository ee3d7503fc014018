// Pixel filters in a render: a sharp edge comes out as the filter's integral across it, each pixel
// still a sum of its own samples.
#include <doctest/doctest.h>

#include <cmath>

#include "sampling/pixel_filter.h"
#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

constexpr int image_width = 16, image_height = 2;

// An unlit white half-plane x < 0 on black, seen face on by an orthographic camera 8 units wide
// on 16 pixels: the edge runs down the film at x = 8 pixels.
SceneDesc half_plane() {
  SceneDesc scene;
  MaterialDesc white;
  white.unlit = true;
  white.base_color = {1, 1, 1};
  add_quad(scene, {-100, -100, 0}, {0, -100, 0}, {0, 100, 0}, {-100, 100, 0}, add_material(scene, white));
  scene.cameras.push_back(ortho_camera({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 1));
  return scene;
}

RenderOptions edge_options(PixelFilterKind filter) {
  RenderOptions o;
  o.width = image_width, o.height = image_height;
  o.spp = 1024;
  o.mode = RenderMode::whitted;
  o.sampler = SamplerKind::sobol;
  o.filter = filter;
  o.env_preset = EnvironmentPreset::none;  // the emitter's edge on black, not the default studio
  return o;
}

// The filter's integral up to t over its whole integral: the share of a pixel's filter that lies
// left of an edge t pixels right of its centre (midpoint rule on 4096 steps).
double integrated_profile(PixelFilterKind kind, float radius, double t) {
  constexpr int steps = 4096;
  double h = 2.0 * radius / steps, below = 0, total = 0;
  for (int i = 0; i < steps; ++i) {
    double x = -radius + (i + 0.5) * h, f = eval_filter_1d(kind, radius, float(x));
    total += f;
    if (x < t) below += f;
  }
  return below / total;
}

}  // namespace

TEST_CASE("pixel filter render: a sharp edge's profile across the pixels is each filter's integrated profile") {
  for (PixelFilterKind kind : {PixelFilterKind::box, PixelFilterKind::triangle, PixelFilterKind::gaussian,
                               PixelFilterKind::mitchell, PixelFilterKind::blackman_harris}) {
    CAPTURE(pixel_filter_name(kind));
    RenderResult r = render_scene(half_plane(), edge_options(kind));
    float radius = default_filter_radius(kind);
    int blurred = 0;
    for (int y = 0; y < image_height; ++y)
      for (int x = 0; x < image_width; ++x) {
        CAPTURE(x);
        double expected = integrated_profile(kind, radius, image_width / 2 - (x + 0.5));
        double got = pixel_mean(r.film.at(x, y)).x;
        CHECK(std::abs(got - expected) < 0.02);
        blurred += expected > 0.02 && expected < 0.98;
      }
    // The box of one pixel keeps the edge sharp; every other filter spreads it over both sides.
    if (kind == PixelFilterKind::box) CHECK(blurred == 0);
    else CHECK(blurred >= 2 * image_height);
  }
}

TEST_CASE("pixel filter render: Mitchell's negative lobes ring on both sides of the edge") {
  // Eight pixels wide, so that the pixels 2.5 pixels from the edge sit on the lobes: about 1.5%
  // above white on the bright side and below black on the dark one.
  RenderOptions o = edge_options(PixelFilterKind::mitchell);
  o.filter_width = 8;
  o.spp = 4096;
  RenderResult r = render_scene(half_plane(), o);
  CHECK(integrated_profile(PixelFilterKind::mitchell, 4, 2.5) > 1.01);
  CHECK(pixel_mean(r.film.at(image_width / 2 - 3, 0)).x > 1.0f);
  CHECK(pixel_mean(r.film.at(image_width / 2 + 2, 0)).x < 0.0f);
  uint32_t negative = 0;
  for (const FilmPixel& p : r.film.pixels) negative += p.negative_samples;
  CHECK(negative > 0);
}

TEST_CASE("pixel filter render: crop tiles of a Mitchell render hold the full render's pixel sums bit for bit") {
  SceneDesc scene = half_plane();
  RenderOptions o = edge_options(PixelFilterKind::mitchell);
  o.spp = 64;
  RenderResult full = render_scene(scene, o);
  for (PixelWindow tile : {PixelWindow{0, 0, 7, 2}, PixelWindow{7, 0, 16, 1}, PixelWindow{7, 1, 16, 2}}) {
    o.crop = tile;
    RenderResult part = render_scene(scene, o);
    for (int y = tile.y0; y < tile.y1; ++y)
      for (int x = tile.x0; x < tile.x1; ++x) {
        const FilmPixel &a = full.film.at(x, y), &b = part.film.at(x - tile.x0, y - tile.y0);
        CHECK(a.sum[0] == b.sum[0]);
        CHECK(a.negative_samples == b.negative_samples);
      }
  }
}
