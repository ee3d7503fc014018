// Lines and points rendered as Embree round curves and spheres: a line covers the pixels its
// width asks for (world units, or pixels at its distance), a point the disc of its sphere, and
// both shade like any surface.
#include <doctest/doctest.h>

#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// An unlit white material: a pixel's value is the fraction of it the stroke covers.
int add_coverage_material(SceneDesc& scene) {
  MaterialDesc m;
  m.model = MaterialModel::metallic_roughness;
  m.base_color = {1, 1, 1};
  m.unlit = true;
  return add_material(scene, m);
}

// A line along x through the origin, as a polyline of `vertices` vertices from x = -2 to 2.
StrokeDesc line_along_x(int material, int vertices, float width) {
  StrokeDesc line;
  line.material = material;
  line.width = width;
  for (int i = 0; i < vertices; ++i) line.positions.push_back({-2 + 4.0f * float(i) / float(vertices - 1), 0, 0});
  for (int i = 0; i + 1 < vertices; ++i) line.segments.push_back(uint32_t(i));
  return line;
}

RenderOptions coverage_render(color3 environment = {0, 0, 0}) {
  RenderOptions o;
  o.width = 64;
  o.height = 64;
  o.spp = 64;
  o.mode = RenderMode::path;
  o.env_color = environment;
  return o;
}

// The sum of column x's pixels: the pixels' worth of height the stroke covers there.
float column_coverage(const Film& film, int x) {
  float sum = 0;
  for (int y = 0; y < film.height; ++y) sum += pixel_mean(film.at(x, y)).x;
  return sum;
}

float image_coverage(const Film& film) {
  float sum = 0;
  for (int x = 0; x < film.width; ++x) sum += column_coverage(film, x);
  return sum;
}

}  // namespace

TEST_CASE("strokes: a line of known width in front of a black background covers that many pixels") {
  // Orthographic, 2 units over 64 pixels: a pixel is 1/32 unit.
  SceneDesc scene;
  scene.strokes.push_back(line_along_x(add_coverage_material(scene), 2, 0.1f));
  scene.cameras.push_back(ortho_camera({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 2));
  Film film = render_scene(scene, coverage_render()).film;
  for (int x : {5, 32, 60}) CHECK(column_coverage(film, x) == doctest::Approx(0.1 * 32).epsilon(0.02));
  CHECK(pixel_mean(film.at(32, 8)).x == 0);  // far from the line: the background
}

TEST_CASE("strokes: --line-width in pixels keeps that width at the line's distance") {
  SceneDesc flat;
  flat.strokes.push_back(line_along_x(add_coverage_material(flat), 2, 0));
  flat.cameras.push_back(ortho_camera({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 2));
  RenderOptions three_pixels = coverage_render();
  three_pixels.line_width = {3, true};
  CHECK(column_coverage(render_scene(flat, three_pixels).film, 20) == doctest::Approx(3).epsilon(0.02));
  // In perspective the width follows each vertex's distance: a dense polyline 5 away keeps 3
  // pixels where it crosses the view's centre, 10 away too.
  for (float distance : {5.0f, 10.0f}) {
    SceneDesc deep;
    deep.strokes.push_back(line_along_x(add_coverage_material(deep), 81, 0));
    deep.cameras.push_back(perspective_camera({0, 0, distance}, {0, 0, -1}, {0, 1, 0}, 45));
    CAPTURE(distance);
    CHECK(column_coverage(render_scene(deep, three_pixels).film, 32) == doctest::Approx(3).epsilon(0.03));
  }
  // World units: 0.05 is 1.6 pixels here, whatever the default.
  RenderOptions world = coverage_render();
  world.line_width = {0.05f, false};
  CHECK(column_coverage(render_scene(flat, world).film, 40) == doctest::Approx(1.6).epsilon(0.02));
}

TEST_CASE("strokes: a point covers the disc of its sphere and shades as a white sphere in a white furnace") {
  SceneDesc scene;
  StrokeDesc point;
  point.kind = StrokeKind::points;
  point.material = add_coverage_material(scene);
  point.width = 0.5f;
  point.center = {0.25f, 0, 0};
  point.positions = {{0, 0, 0}};
  scene.strokes.push_back(point);
  scene.cameras.push_back(ortho_camera({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 2));
  // A disc of radius 0.25 is pi / 16 square units, 1024 pixels to the unit.
  CHECK(image_coverage(render_scene(scene, coverage_render()).film) == doctest::Approx(pi / 16 * 1024).epsilon(0.02));
  scene.materials[0].unlit = false;
  scene.materials[0].metallic = 0;
  scene.materials[0].specular = 0;  // exactly Lambertian
  color3 lit = pixel_mean(render_scene(scene, coverage_render({1, 1, 1})).film.at(40, 32));
  CHECK(lit.x == doctest::Approx(1).epsilon(0.02));
}
