// Effect analysis, specialised integrators and switching effects off.
#include <doctest/doctest.h>

#include <cmath>

#include "load_scene.h"
#include "scene/effects.h"
#include "support/scene_builders.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

uint32_t asset_effects(const char* asset) {
  return analyze_effects(load_scene(source_path(asset).string())).mask;
}

bool films_identical(const Film& a, const Film& b) {
  for (size_t i = 0; i < a.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      if (a.pixels[i].sum[c] != b.pixels[i].sum[c]) return false;
  return true;
}

}  // namespace

TEST_CASE("effects: each .scene asset calls for exactly the effects its content needs") {
  CHECK(effect_names(asset_effects("assets/first-render.scene")) == "direct,shadows,reflection,emission,indirect");
  CHECK(effect_names(asset_effects("assets/showcase.scene")) ==
        "direct,ambient,shadows,transparent-shadows,reflection,refraction,emission,indirect");
  CHECK(effect_names(asset_effects("assets/room-older-format.scene")) == "shadows,reflection,emission,indirect");
}

TEST_CASE("effects: --effects parses additions, removals, all and none, and rejects unknown names") {
  CHECK(apply_effects_override(effect_shadows | effect_reflection, "-shadows") == effect_reflection);
  CHECK(apply_effects_override(0, "+textures,environment") == (effect_textures | effect_environment));
  CHECK(apply_effects_override(effect_shadows, "all") == effect_all);
  CHECK(apply_effects_override(effect_all, "none") == 0);
  CHECK_THROWS_AS(apply_effects_override(0, "-sparkles"), std::invalid_argument);
}

TEST_CASE("effects: the specialised integrator and the generic one (--effects=all) give identical images") {
  for (const char* asset : {"assets/first-render.scene", "assets/showcase.scene", "assets/room-older-format.scene"}) {
    for (RenderMode mode : {RenderMode::whitted, RenderMode::path}) {
      SceneDesc scene = load_scene(source_path(asset).string());
      RenderOptions o;
      o.width = 24, o.height = 24, o.spp = 4, o.mode = mode;
      RenderResult specialised = render_scene(scene, o);
      o.effects = "all";
      RenderResult generic = render_scene(scene, o);
      CAPTURE(asset);
      CAPTURE(int(mode));
      CHECK(generic.settings.compiled_variant == effect_all);
      CHECK(specialised.settings.compiled_variant != effect_all);
      CHECK(films_identical(specialised.film, generic.film));
    }
  }
}

TEST_CASE("effects: switching shadows off brightens exactly the shadowed pixels, -reflection removes mirror images") {
  SceneDesc scene;
  add_plane(scene, {0, 0, 0}, {0, 1, 0}, add_diffuse(scene, {0.5f, 0.5f, 0.5f}));
  MaterialDesc mirror;
  mirror.kd = {0.2f, 0.2f, 0.2f};
  mirror.kr = {0.7f, 0.7f, 0.7f};
  add_sphere(scene, {0, 1, 0}, 0.5f, add_material(scene, mirror));
  scene.lights.push_back(point_light({0, 4, 0}, {40, 40, 40}));
  scene.cameras.push_back(ortho_camera({0, 10, 0}, {0, -1, 0}, {0, 0, -1}, 4));
  RenderOptions o;
  o.width = 16, o.height = 16, o.spp = 1, o.mode = RenderMode::whitted;
  Film lit = render_scene(scene, o).film;
  o.effects = "-shadows";
  Film unshadowed = render_scene(scene, o).film;
  // Plane pixels just outside the sphere's silhouette but inside its shadow (radius 0.5..0.625).
  int brighter = 0, unchanged = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      float a = pixel_mean(lit.at(x, y)).x, b = pixel_mean(unshadowed.at(x, y)).x;
      CHECK(b >= a);
      if (b > a) ++brighter;
      else ++unchanged;
    }
  CHECK(brighter > 0);
  CHECK(unchanged > brighter);
  o.effects = "-reflection";
  Film unreflected = render_scene(scene, o).film;
  // The sphere's rim mirrors the lit plane; without reflection only its dull diffuse part is left.
  double with_reflection = 0, without_reflection = 0;
  for (size_t i = 0; i < lit.pixels.size(); ++i) {
    with_reflection += pixel_mean(lit.pixels[i]).x;
    without_reflection += pixel_mean(unreflected.pixels[i]).x;
  }
  CHECK(without_reflection < with_reflection);
}

TEST_CASE("effects: a normal map alone (no other texture) perturbs shading, -normal-maps flattens it") {
  // Regression: with normal maps but no color textures the material was resolved once per
  // render, so every pixel used the normal-map texel at uv (0, 0).
  SceneDesc scene = load_scene(source_path("assets/models/normal-mapped-quad.gltf").string());
  CHECK(effect_names(analyze_effects(scene).mask) == "direct,shadows,reflection,normal-maps,indirect,single-sided");
  RenderOptions o;
  o.width = 48, o.height = 48, o.spp = 1, o.mode = RenderMode::whitted;
  Film bumpy = render_scene(scene, o).film;
  o.effects = "-normal-maps";
  Film flat = render_scene(scene, o).film;
  int changed = 0, lit = 0;
  for (size_t i = 0; i < bumpy.pixels.size(); ++i) {
    float a = pixel_mean(bumpy.pixels[i]).x, b = pixel_mean(flat.pixels[i]).x;
    if (b > 0.05f) ++lit, changed += std::abs(a - b) > 0.05f * b;
  }
  CHECK(lit > 500);
  CHECK(changed > lit / 4);
}

TEST_CASE("effects: glTF and OBJ assets call for the effects their content needs") {
  // glTF materials are single-sided unless they say doubleSided; OBJ ones are double-sided.
  CHECK(effect_names(asset_effects("assets/cornell.gltf")) == "shadows,emission,indirect,single-sided");
  CHECK(effect_names(asset_effects("assets/models/checker-cube.gltf")) ==
        "direct,shadows,reflection,textures,indirect,single-sided");
  CHECK(effect_names(asset_effects("assets/models/textured-cube.obj")) == "textures");
}
