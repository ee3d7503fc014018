// Single-sided materials (glTF doubleSided false): camera rays pass through their back faces,
// shadow rays and bounces meet every face, a mirroring node turns which side is the front, and
// single rays, Embree packets and streams agree on all of it, in both integrators.
#include <doctest/doctest.h>

#include "load_scene.h"
#include "loaders/gltf_builder.h"
#include "scene/effects.h"
#include "support/scene_builders.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// An unlit red unit quad facing +z, placed by a node with `node_extra` members, seen from z = -3
// (from behind) by a camera looking along +z (a half turn about y).
SceneDesc quad_seen_from_behind(bool double_sided, const std::string& node_extra = "") {
  GltfBuilder b = quad_builder();
  std::string gltf = b.gltf(
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,\"material\":0}]}],"
      "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,0,0,1]},\"doubleSided\":" +
      std::string(double_sided ? "true" : "false") +
      ",\"extensions\":{\"KHR_materials_unlit\":{}}}],\"extensionsUsed\":[\"KHR_materials_unlit\"],"
      "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.5,\"znear\":0.1}}],"
      "\"nodes\":[{\"mesh\":0" + node_extra + "},{\"camera\":0,\"translation\":[0.5,0.5,-3],\"rotation\":[0,1,0,0]}],"
      "\"scenes\":[{\"nodes\":[0,1]}]");
  ScratchDir dir("single-sided");
  return load_scene(dir.write("quad.gltf", gltf).string());
}

// The centre pixel of `scene` rendered in `mode` with every way of tracing camera rays; checks
// they agree bit for bit and returns the colour.
// Camera-ray packets and the full batch sum each pixel to the bits of paths traced one by one
// (`alone`, rendered with o.path_batching none).
void check_batchings_agree(const SceneDesc& scene, RenderOptions o, const RenderResult& alone) {
  for (PathBatching batching : {PathBatching::camera_rays, PathBatching::all_rays}) {
    CAPTURE(int(batching));
    o.path_batching = batching;
    RenderResult together = render_scene(scene, o);
    for (size_t i = 0; i < alone.film.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c) CHECK(together.film.pixels[i].sum[c] == alone.film.pixels[i].sum[c]);
  }
}

color3 centre_colour(const SceneDesc& scene, RenderMode mode) {
  RenderOptions o;
  o.width = 9, o.height = 9, o.spp = 2, o.mode = mode, o.env_color = color3{0, 0, 1};
  o.path_batching = PathBatching::none;
  RenderResult alone = render_scene(scene, o);
  check_batchings_agree(scene, o, alone);
  return pixel_mean(alone.film.at(4, 4));
}

}  // namespace

TEST_CASE("single-sided: a back face is not seen by camera rays, a double-sided one is") {
  for (RenderMode mode : {RenderMode::whitted, RenderMode::path}) {
    CAPTURE(int(mode));
    SceneDesc single = quad_seen_from_behind(false);
    CHECK(analyze_effects(single).has(effect_single_sided));
    CHECK(centre_colour(single, mode) == color3{0, 0, 1});  // the background
    SceneDesc both = quad_seen_from_behind(true);
    CHECK_FALSE(analyze_effects(both).has(effect_single_sided));
    CHECK(centre_colour(both, mode) == color3{1, 0, 0});
    // --effects=-single-sided shows the back face again.
    RenderOptions o;
    o.width = 9, o.height = 9, o.spp = 1, o.mode = mode, o.effects = "-single-sided";
    CHECK(pixel_mean(render_scene(single, o).film.at(4, 4)) == color3{1, 0, 0});
  }
}

TEST_CASE("single-sided: a node that mirrors through the quad's plane turns its front to the camera") {
  for (RenderMode mode : {RenderMode::whitted, RenderMode::path}) {
    CAPTURE(int(mode));
    // Scale z by -1: the quad stays in place, its front (the mirrored normal) now faces -z.
    CHECK(centre_colour(quad_seen_from_behind(false, ",\"scale\":[1,1,-1]"), mode) == color3{1, 0, 0});
    // A mirror in x keeps the normal: still seen from behind (the quad moves to x in [-1, 0]).
    CHECK(centre_colour(quad_seen_from_behind(false, ",\"scale\":[-1,1,1],\"translation\":[1,0,0]"), mode) ==
          color3{0, 0, 1});
  }
}

TEST_CASE("single-sided: shadow rays and see-through camera rays meet faces as they should") {
  // Looking down on a floor (image top towards -z); above it a green single-sided card facing
  // down (its back to the camera and to the light above it), and further along z a
  // half-transparent blended veil over a second such card.
  SceneDesc scene;
  add_quad(scene, {-4, 0, -4}, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, add_diffuse(scene, {0.8f, 0.8f, 0.8f}));
  MaterialDesc green;
  green.kd = {0, 0.8f, 0}, green.double_sided = false;
  int card = add_material(scene, green);
  add_quad(scene, {-0.5f, 1, -2}, {0.5f, 1, -2}, {0.5f, 1, -1}, {-0.5f, 1, -1}, card);  // facing down
  add_quad(scene, {-0.5f, 1, 1}, {0.5f, 1, 1}, {0.5f, 1, 2}, {-0.5f, 1, 2}, card);
  MaterialDesc veil;
  veil.kd = {0.5f, 0.5f, 0.5f}, veil.alpha = 0.5f, veil.alpha_mode = AlphaMode::blend;
  add_quad(scene, {-0.7f, 1.5f, 0.8f}, {-0.7f, 1.5f, 2.2f}, {0.7f, 1.5f, 2.2f}, {0.7f, 1.5f, 0.8f},
           add_material(scene, veil));  // facing up
  scene.lights.push_back(point_light({0, 3, -1.5f}, {9, 9, 9}));
  scene.cameras.push_back(ortho_camera({0, 5, 0}, {0, -1, 0}, {0, 0, -1}, 6));
  for (RenderMode mode : {RenderMode::whitted, RenderMode::path}) {
    CAPTURE(int(mode));
    RenderOptions o;  // direct light only: no light bounced off the green fronts
    o.width = 24, o.height = 24, o.spp = 4, o.mode = mode, o.env_color = color3{0, 0, 0}, o.max_depth = 1;
    o.path_batching = PathBatching::none;
    RenderResult alone = render_scene(scene, o);
    // Under the first card: the floor, not the card's back, and in the card's shadow.
    color3 under = pixel_mean(alone.film.at(12, 6)), beside = pixel_mean(alone.film.at(3, 6));
    CHECK(under.y == under.x);  // no green
    CHECK(under.x < 0.5f * beside.x);
    // Through the veil: the floor under the second card, never the card's green back.
    color3 veiled = pixel_mean(alone.film.at(12, 18));
    CHECK(veiled.x > 0);
    CHECK(veiled.y == doctest::Approx(veiled.x).epsilon(1e-5));
    check_batchings_agree(scene, o, alone);
  }
}
