// A rough coloured metal under a uniform white environment, rendered end to end from a glTF
// file: the case of Khronos' MultiUVTest (the glTF default material, metallic 1 and roughness 1,
// over a yellow sRGB base colour texture). The expected values are Blender 3.4 Cycles' with the
// Principled BSDF's Multiscatter GGX; its importer's default, single-scattering GGX, returns
// (0.31, 0.29, 0.10) for the same face, a third of the energy.
#include <doctest/doctest.h>

#include "load_scene.h"
#include "loaders/gltf_builder.h"
#include "support/scene_builders.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// A 2x2 unit quad facing +z with a 1x1 base colour texture of sRGB `texel` on TEXCOORD_0,
// metallic and roughness left to the glTF defaults (1 and 1), seen head on from z = 3.
SceneDesc textured_metal_quad(ScratchDir& dir, std::vector<unsigned char> texel) {
  write_texel_bytes(dir.file("base.png"), 1, 1, 3, texel);
  GltfBuilder b;
  b.floats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, "VEC3", 3);
  b.indices({0, 1, 2, 0, 2, 3});
  b.floats({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2", 2);
  std::string gltf = b.gltf(
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"TEXCOORD_0\":2},\"indices\":1,"
      "\"material\":0}]}],"
      "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}}}],"
      "\"textures\":[{\"source\":0}],\"images\":[{\"uri\":\"base.png\"}],"
      "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.3,\"znear\":0.1}}],"
      "\"nodes\":[{\"mesh\":0},{\"camera\":0,\"translation\":[0,0,3]}],\"scenes\":[{\"nodes\":[0,1]}]");
  return load_scene(dir.write("metal.gltf", gltf).string());
}

color3 film_mean(const Film& film) {
  color3 sum{0, 0, 0};
  for (const FilmPixel& p : film.pixels) sum = sum + pixel_mean(p);
  return sum * (1.0f / float(film.pixels.size()));
}

}  // namespace

TEST_CASE("coloured metal: a rough yellow metal in a white furnace reflects what Cycles' Multiscatter GGX does") {
  ScratchDir dir("coloured-metal-furnace");
  // MultiUVTest's yellow, sRGB (255, 247, 153): linear (1, 0.930, 0.319).
  SceneDesc scene = textured_metal_quad(dir, {255, 247, 153});
  RenderOptions o;
  o.width = o.height = 8;
  o.spp = 256;
  o.mode = RenderMode::path;
  o.max_depth = 8;
  o.env_color = color3{1, 1, 1};
  color3 face = film_mean(render_scene(scene, o).film);
  INFO("face ", face.x, " ", face.y, " ", face.z);
  // Cycles, Multiscatter GGX, 256 spp: (0.981, 0.850, 0.154), the face seen 14 degrees off its normal.
  CHECK(face.x == doctest::Approx(0.981).epsilon(0.03));
  CHECK(face.y == doctest::Approx(0.850).epsilon(0.03));
  CHECK(face.z == doctest::Approx(0.154).epsilon(0.12));
  // Multiple scattering saturates: blue keeps less than its share of F0 that red keeps.
  CHECK(face.z / face.x < 0.319f);
}
