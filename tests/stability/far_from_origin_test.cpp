// Far from the origin exactly as at the origin: render space (render/render_space.h) puts the
// origin next to the camera, so a scene offset by 1e6 or 1e7 renders like the same scene at the
// origin, every pixel, edges included, with perspective and orthographic cameras
// (docs/stability.md, case 1b).
#include <doctest/doctest.h>

#include <cmath>

#include "stability/film_checks.h"
#include "stability/scene_pieces.h"

using namespace radiant;
using namespace radiant::test;

namespace {

constexpr int image_size = 32;

// A sphere and a box on a plane, a point light, an ambient light and a camera, all on integer
// coordinates: at 1e7 the float spacing is 1, so the offset scene is exactly the scene the file
// would describe. The camera looks down at the objects, whose shadows fall towards it.
SceneDesc scene_at(vec3 offset, Projection projection) {
  SceneDesc scene;
  MaterialDesc material;
  material.kd = material.ka = {0.5f, 0.5f, 0.5f};
  int m = add_material(scene, material);
  add_plane(scene, offset, {0, 1, 0}, m);
  add_sphere(scene, vec3{-3, 3, 0} + offset, 3, m);
  add_box(scene, vec3{1, 0, -2} + offset, {4, 4, 4}, m);
  scene.lights.push_back(point_light(vec3{6, 20, -10} + offset, {2000, 2000, 2000}));
  LightDesc ambient;
  ambient.kind = LightKind::ambient;
  ambient.intensity = {0.1f, 0.1f, 0.1f};
  scene.lights.push_back(ambient);
  vec3 forward = normalize(vec3{0, -6, -24});
  scene.cameras.push_back(projection == Projection::perspective
                              ? perspective_camera(vec3{0, 9, 24} + offset, forward, {0, 1, 0}, 40)
                              : ortho_camera(vec3{0, 9, 24} + offset, forward, {0, 1, 0}, 18));
  return scene;
}

struct PixelDifference {
  size_t differing = 0;      // pixels not bit-identical
  float largest_relative = 0;  // over every pixel and channel
};

PixelDifference difference(const Film& a, const Film& b) {
  PixelDifference d;
  REQUIRE(a.pixels.size() == b.pixels.size());
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    color3 x = pixel_mean(a.pixels[i]), y = pixel_mean(b.pixels[i]);
    if (x.x != y.x || x.y != y.y || x.z != y.z) ++d.differing;
    for (int c = 0; c < 3; ++c)
      d.largest_relative = std::max(d.largest_relative, std::abs(x[c] - y[c]) / std::max(std::abs(x[c]), 1e-3f));
  }
  return d;
}

// The image must show every region the comparison is about: lit tops, shadows and background.
void check_image_has_content(const Film& film) {
  size_t bright = 0, ambient_only = 0;
  for (const FilmPixel& p : film.pixels) {
    float v = pixel_mean(p).x;
    bright += v > 0.2f;
    ambient_only += v > 0.04f && v < 0.06f;
  }
  CHECK(bright > 100);
  CHECK(ambient_only > 20);
}

}  // namespace

TEST_CASE("stability: a scene 1e7 away renders bit for bit as at the origin, perspective and orthographic") {
  for (Projection projection : {Projection::perspective, Projection::orthographic}) {
    CAPTURE(int(projection));
    RenderResult origin = render_finite(scene_at({0, 0, 0}, projection), whitted_options(image_size));
    check_image_has_content(origin.film);
    // 1e7 is a multiple of the render-space grid here (128), so render space is identical.
    for (vec3 offset : {vec3{1e7f, 1e7f, 1e7f}, vec3{1e7f, -1e7f, 0}, vec3{-1e7f, 0, 1e7f}}) {
      CAPTURE(offset.x);
      CAPTURE(offset.y);
      RenderResult far = render_finite(scene_at(offset, projection), whitted_options(image_size));
      CHECK(difference(origin.film, far.film).differing == 0);
      CHECK(far.stats.untraceable_rays == 0);
    }
  }
}

TEST_CASE("stability: a scene 1e6 away matches the origin render in every pixel, perspective and orthographic") {
  for (Projection projection : {Projection::perspective, Projection::orthographic}) {
    CAPTURE(int(projection));
    RenderResult origin = render_finite(scene_at({0, 0, 0}, projection), whitted_options(image_size));
    // 1e6 is not a multiple of the grid: the render origin lands up to 64 units from the camera,
    // where float spacing is 8e-6, against 2e-6 at the origin. Every pixel agrees to rounding.
    for (vec3 offset : {vec3{1e6f, 1e6f, 1e6f}, vec3{-1e6f, 1e6f, -1e6f}}) {
      CAPTURE(offset.x);
      RenderResult far = render_finite(scene_at(offset, projection), whitted_options(image_size));
      CHECK(difference(origin.film, far.film).largest_relative < 1e-4f);
    }
  }
}

TEST_CASE("stability: a path-traced scene 1e7 away gives the same samples as at the origin") {
  RenderOptions options = path_options(16, 4, 3);
  RenderResult origin = render_finite(scene_at({0, 0, 0}, Projection::perspective), options);
  RenderResult far = render_finite(scene_at({1e7f, -1e7f, 1e7f}, Projection::perspective), options);
  CHECK(difference(origin.film, far.film).differing == 0);
}
