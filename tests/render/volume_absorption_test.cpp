// KHR_materials_volume: Beer-Lambert absorption inside closed transmissive meshes, so tinted glass
// is darker where it is thicker.
#include <doctest/doctest.h>

#include <cmath>

#include "scene/effects.h"
#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// A closed box from `low` to `high`, faces counter-clockwise seen from outside (outward normals).
void add_box(SceneDesc& scene, vec3 low, vec3 high, int material) {
  MeshDesc mesh;
  mesh.material = material;
  for (int i = 0; i < 8; ++i)
    mesh.positions.push_back({(i == 1 || i == 2 || i == 5 || i == 6) ? high.x : low.x,
                              (i == 2 || i == 3 || i == 6 || i == 7) ? high.y : low.y, i >= 4 ? high.z : low.z});
  mesh.indices = {0, 3, 2, 0, 2, 1, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                  3, 7, 6, 3, 6, 2, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5};
  scene.meshes.push_back(mesh);
  InstanceDesc instance;
  instance.mesh = int(scene.meshes.size()) - 1;
  scene.instances.push_back(instance);
}

// Clear glass of ior 1 (no Fresnel reflection, no bending): only the volume changes the light.
MaterialDesc tinted_glass(float thickness) {
  MaterialDesc m;
  m.model = MaterialModel::metallic_roughness;
  m.base_color = {1, 1, 1};
  m.metallic = 0;
  m.roughness = 0;
  m.transmission = 1;
  m.ior = 1;
  m.thickness = thickness;
  m.attenuation_distance = 0.5f;
  m.attenuation_color = {0.8f, 0.5f, 0.2f};
  return m;
}

// Two boxes seen from the front by an orthographic camera (8 pixels per unit) under a white sky:
// one 1 deep on the left (x in [-1.5, -0.5]), one 2 deep on the right (x in [0.5, 1.5]).
SceneDesc two_glass_blocks(float thickness) {
  SceneDesc scene;
  int glass = add_material(scene, tinted_glass(thickness));
  add_box(scene, {-1.5f, -0.5f, -0.5f}, {-0.5f, 0.5f, 0.5f}, glass);
  add_box(scene, {0.5f, -0.5f, -1}, {1.5f, 0.5f, 1}, glass);
  scene.cameras.push_back(ortho_camera({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 2));
  return scene;
}

RenderOptions sky_options() {
  RenderOptions o;
  o.width = 32;
  o.height = 16;
  o.spp = 4;
  o.mode = RenderMode::path;
  o.env_color = color3{1, 1, 1};
  return o;
}

}  // namespace

TEST_CASE("volume: light through tinted glass keeps attenuation colour ^ (length / attenuation distance)") {
  SceneDesc scene = two_glass_blocks(1);
  CHECK(analyze_effects(scene).has(effect_absorption));
  Film film = render_scene(scene, sky_options()).film;
  color3 thin = pixel_mean(film.at(8, 8)), thick = pixel_mean(film.at(24, 8)), sky = pixel_mean(film.at(16, 8));
  // 1 deep at a distance of 0.5: the colour squared; 2 deep: to the fourth.
  CHECK(thin.x == doctest::Approx(0.8 * 0.8).epsilon(1e-4));
  CHECK(thin.y == doctest::Approx(0.5 * 0.5).epsilon(1e-4));
  CHECK(thin.z == doctest::Approx(0.2 * 0.2).epsilon(1e-4));
  CHECK(thick.x == doctest::Approx(std::pow(0.8, 4)).epsilon(1e-4));
  CHECK(thick.z == doctest::Approx(std::pow(0.2, 4)).epsilon(1e-4));
  CHECK(sky.x == 1);
}

TEST_CASE("volume: a thin wall (thickness 0), no attenuation distance or -absorption let the light through") {
  SceneDesc thin_walled = two_glass_blocks(0);
  CHECK_FALSE(analyze_effects(thin_walled).has(effect_absorption));
  CHECK(pixel_mean(render_scene(thin_walled, sky_options()).film.at(24, 8)).x == doctest::Approx(1));
  SceneDesc clear = two_glass_blocks(1);
  clear.materials[0].attenuation_distance = 0;  // infinite
  CHECK(pixel_mean(render_scene(clear, sky_options()).film.at(24, 8)).z == doctest::Approx(1));
  RenderOptions off = sky_options();
  off.effects = "-absorption";
  CHECK(pixel_mean(render_scene(two_glass_blocks(1), off).film.at(24, 8)).z == doctest::Approx(1));
}
