// Renders with the light BVH converge to the same image as power sampling and as BSDF sampling
// alone: the choice of light changes only the noise, and MIS weighs a light hit by a BSDF-sampled
// ray with the probability the BVH would have chosen it.
#include <doctest/doctest.h>

#include <cmath>

#include "support/film_measures.h"
#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// Twelve lamps of four colors facing down onto a floor, two emissive spheres, and (optionally)
// point lights, a spot and a directional light; a uniform sky.
SceneDesc lamp_room(bool delta_lights) {
  SceneDesc scene;
  add_quad(scene, {-3, 0, -3}, {-3, 0, 3}, {3, 0, 3}, {3, 0, -3}, add_diffuse(scene, {0.6f, 0.6f, 0.6f}));
  color3 colors[4] = {{2, 2, 2}, {4, 1, 0.5f}, {0.5f, 1, 4}, {1, 3, 1}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j) {
      MaterialDesc lamp;
      lamp.emission = colors[(i + j) % 4];
      lamp.double_sided = false;
      int m = add_material(scene, lamp);
      float x = -2.25f + 1.5f * float(i), z = -1.5f + 1.5f * float(j), y = 1.2f + 0.2f * float(i);
      add_quad(scene, {x - 0.25f, y, z - 0.25f}, {x + 0.25f, y, z - 0.25f}, {x + 0.25f, y, z + 0.25f},
               {x - 0.25f, y, z + 0.25f}, m);
    }
  MaterialDesc glow;
  glow.emission = {3, 2, 1};
  add_sphere(scene, {-1, 0.3f, 1.8f}, 0.3f, add_material(scene, glow));
  add_sphere(scene, {1.5f, 0.2f, -2}, 0.2f, add_material(scene, glow));
  if (delta_lights) {
    scene.lights.push_back(point_light({0.5f, 0.8f, 0.5f}, {1, 1, 1}));
    LightDesc spot = point_light({-2, 2, -2}, {4, 4, 4});
    spot.kind = LightKind::spot;
    spot.direction = normalize(vec3{1, -2, 1});
    spot.use_cone = true;
    spot.inner_cone = 0.2f, spot.outer_cone = 0.5f;
    scene.lights.push_back(spot);
    LightDesc sun;
    sun.kind = LightKind::directional;
    sun.direction = normalize(vec3{-0.2f, -1, 0.3f});
    sun.intensity = {0.3f, 0.3f, 0.3f};
    scene.lights.push_back(sun);
  }
  scene.cameras.push_back(perspective_camera({0, 4, 5}, {0, -4, -5}, {0, 1, 0}, 55));
  scene.environment.color = {0.05f, 0.07f, 0.1f};
  return scene;
}

RenderOptions options(RenderMode mode, LightSampler sampler, int spp) {
  RenderOptions o;
  o.width = o.height = 32;
  o.spp = spp;
  o.max_depth = 2;
  o.mode = mode;
  o.light_sampler = sampler;
  return o;
}

}  // namespace

TEST_CASE("light BVH render: the same image as power sampling, within the noise, with every kind of light") {
  SceneDesc scene = lamp_room(true);
  RenderResult bvh = render_scene(scene, options(RenderMode::path, LightSampler::bvh, 64));
  RenderResult power = render_scene(scene, options(RenderMode::path, LightSampler::power, 64));
  REQUIRE(bvh.settings.light_sampler == LightSampler::bvh);
  REQUIRE(power.settings.light_sampler == LightSampler::power);
  CHECK(largest_block_z(bvh.film, power.film) < 4);
}

TEST_CASE("light BVH render: MIS with the BVH's probabilities agrees with BSDF sampling alone (naive)") {
  SceneDesc scene = lamp_room(false);
  RenderResult bvh = render_scene(scene, options(RenderMode::path, LightSampler::bvh, 64));
  RenderResult naive = render_scene(scene, options(RenderMode::naive, LightSampler::bvh, 256));
  REQUIRE(bvh.settings.light_sampler == LightSampler::bvh);
  CHECK(largest_block_z(bvh.film, naive.film) < 4);
}

TEST_CASE("light BVH render: less noise than power sampling at equal samples among many small lights") {
  SceneDesc scene = lamp_room(false);
  auto mean_variance = [](const Film& film) {
    double sum = 0;
    for (const FilmPixel& p : film.pixels) sum += luminance(pixel_mean_variance(p));
    return sum / double(film.pixels.size());
  };
  double bvh = mean_variance(render_scene(scene, options(RenderMode::path, LightSampler::bvh, 16)).film);
  double power = mean_variance(render_scene(scene, options(RenderMode::path, LightSampler::power, 16)).film);
  CHECK(bvh < 0.75 * power);  // measured: 0.59
}
