// Every channel radiant writes is finite, AOVs and variance included, however bright the scene:
// a CI gate reading an infinite variance would pass any image as noise.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "loaders/gltf_builder.h"
#include "support/scene_builders.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;
namespace fs = std::filesystem;

namespace {


const char* all_aovs = " --aov albedo,normal,depth,variance,spp";

// "" when every value of every channel is finite, else the first that is not.
std::string first_nonfinite_value(const TestImage& image) {
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < image.channels; ++c)
        if (!std::isfinite(image.at(x, y, c)))
          return image.channel_names[size_t(c)] + " at (" + std::to_string(x) + ", " + std::to_string(y) +
                 ") is " + std::to_string(image.at(x, y, c));
  return "";
}

// A small square over a larger one, both facing +Z, seen from a perspective camera at z = 3: the
// small square's edges cross pixels, so their samples mix its radiance with the other's.
std::string two_squares(const std::string& small_material, const std::string& extensions_used,
                        const std::string& extra_nodes = "", const std::string& extra = "") {
  GltfBuilder b;
  b.floats({-0.3f, -0.3f, 0, 0.3f, -0.3f, 0, 0.3f, 0.3f, 0, -0.3f, 0.3f, 0}, "VEC3", 3);
  b.indices({0, 1, 2, 0, 2, 3});
  b.floats({-2, -2, -0.5f, 2, -2, -0.5f, 2, 2, -0.5f, -2, 2, -0.5f}, "VEC3", 3);
  std::string nodes = "{\"mesh\":0},{\"mesh\":1},{\"camera\":0,\"translation\":[0,0,3]}" + extra_nodes;
  return b.gltf("\"extensionsUsed\":[" + extensions_used + "]," +
                "\"materials\":[" + small_material + ",{\"pbrMetallicRoughness\":{\"metallicFactor\":0}}]," +
                "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,\"material\":0}]}," +
                "{\"primitives\":[{\"attributes\":{\"POSITION\":2},\"indices\":1,\"material\":1}]}]," +
                "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.6,\"znear\":0.1}}]," +
                "\"nodes\":[" + nodes + "],\"scenes\":[{\"nodes\":[0,1,2" +
                (extra_nodes.empty() ? "" : ",3") + "]}]" + extra);
}

// Renders `scene` to an EXR with every AOV and returns the image.
TestImage render_all_channels(const ScratchDir& dir, const fs::path& scene, const std::string& flags = " --mode path") {
  fs::path out = dir.file("out.exr");
  CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(out) +
                                " --spp 4 --width 16 --height 16 --quiet" + all_aovs + flags);
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  return read_image(out);
}

}  // namespace

TEST_CASE("finite output: emission of 1e38 gives finite variance and AOVs in every pixel") {
  ScratchDir dir("finite-emission");
  fs::path scene = dir.write(
      "bright.gltf", two_squares("{\"emissiveFactor\":[1,1,1],\"extensions\":{\"KHR_materials_emissive_strength\":"
                                 "{\"emissiveStrength\":1e38}}}",
                                 "\"KHR_materials_emissive_strength\""));
  TestImage image = render_all_channels(dir, scene);
  CHECK(first_nonfinite_value(image) == "");
}

TEST_CASE("finite output: a point light of 1e38 gives finite variance and AOVs in every pixel") {
  ScratchDir dir("finite-light");
  fs::path scene = dir.write(
      "bright.gltf", two_squares("{}", "\"KHR_lights_punctual\"",
                                 ",{\"translation\":[0.5,0.5,1],\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}}}",
                                 ",\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[{\"type\":\"point\","
                                 "\"intensity\":1e38}]}}"));
  // Whitted sums the light at every jittered sample: pixels across a shading gradient vary by ~1e36.
  CHECK(first_nonfinite_value(render_all_channels(dir, scene, " --mode whitted")) == "");
  // The path tracer picks lights by power, 1e39 here: beyond a float, it must not become zero.
  TestImage path = render_all_channels(dir, scene);
  CHECK(first_nonfinite_value(path) == "");
  CHECK(path.at(8, 8, 0) > 1e30f);
}

TEST_CASE("finite output: environment pixels of 3e38 give finite variance and AOVs in every pixel") {
  ScratchDir dir("finite-environment");
  fs::path scene = dir.write("squares.gltf", two_squares("{}", ""));
  std::vector<float> sky(8 * 4 * 3, 0.0f);
  for (size_t i = 0; i < sky.size(); i += 6) sky[i] = sky[i + 1] = sky[i + 2] = 3e38f;  // every other pixel
  write_test_image(dir.file("sky.exr"), 8, 4, {"R", "G", "B"}, sky);
  TestImage image = render_all_channels(dir, scene, " --mode path --env " + quoted(dir.file("sky.exr")));
  CHECK(first_nonfinite_value(image) == "");
}

TEST_CASE("finite output: a sample whose AOVs are not finite is dropped and counted, like its color") {
  // NaN vertex colors never come from a file (the loaders refuse them); built here to reach the film.
  SceneDesc scene;
  MaterialDesc material;
  material.kd = {1, 1, 1};
  int white = add_material(scene, material);
  add_quad(scene, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, white);
  float nan = std::numeric_limits<float>::quiet_NaN();
  scene.meshes[0].colors.assign(4, vec4{nan, nan, nan, 1});
  scene.cameras.push_back(ortho_camera({0, 0, 2}, {0, 0, -1}, {0, 1, 0}, 1));  // sees only the quad
  RenderOptions options;
  options.width = options.height = 4;
  options.spp = 2;
  options.mode = RenderMode::whitted;
  options.aovs = {"albedo", "normal", "depth", "variance", "spp"};
  RenderResult result = render_scene(scene, options);
  CHECK(result.stats.rays.nonfinite_samples == 4 * 4 * 2);
  OutputImage image = film_to_image(result.film, options.aovs);
  for (size_t i = 0; i < image.pixels.size(); ++i) REQUIRE(std::isfinite(image.pixels[i]));
}
