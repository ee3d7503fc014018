// A glTF animation sampled over the shutter (--shutter): node transforms, morphed vertices and
// cameras become motion steps, as many as the keys inside the shutter need; what holds still
// gets none, and a shutter over a still scene renders the unblurred image to the bit.
#include <doctest/doctest.h>

#include <filesystem>

#include "load_scene.h"
#include "loaders/gltf_builder.h"
#include "scene/effects.h"
#include "support/scene_builders.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// A triangle at node 0 (with a morph target, +3 in z) and a camera at node 1, the animation
// moving `path` of node `target` through `values` at `times` seconds.
std::string animated(const std::string& path, int target, const std::vector<float>& times,
                     const std::vector<float>& values, const std::string& type) {
  GltfBuilder b;
  b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
  b.floats({0, 0, 3, 0, 0, 3, 0, 0, 3}, "VEC3", 3);
  int input = b.floats(times, "SCALAR", 1);
  int output = b.floats(values, type, type == "VEC4" ? 4 : type == "VEC3" ? 3 : 1);
  return b.gltf(
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"targets\":[{\"POSITION\":1}]}],"
      "\"weights\":[0]}],"
      "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.8,\"znear\":0.1}}],"
      "\"nodes\":[{\"mesh\":0},{\"camera\":0,\"translation\":[0,0,5]}],\"scenes\":[{\"nodes\":[0,1]}],\"scene\":0,"
      "\"animations\":[{\"channels\":[{\"sampler\":0,\"target\":{\"node\":" + std::to_string(target) + ",\"path\":\"" +
      path + "\"}}],\"samplers\":[{\"input\":" + std::to_string(input) + ",\"output\":" + std::to_string(output) + "}]}]");
}

SceneDesc with_shutter(const ScratchDir& dir, const std::string& gltf, double seconds, double open, double close) {
  LoadOptions options;
  options.animation_time = seconds;
  options.shutter = LoadOptions::Shutter{open, close};
  return load_scene(dir.write("animated.gltf", gltf).string(), options);
}

float x_translation(const mat4& m) { return m.m[0][3]; }

}  // namespace

TEST_CASE("gltf motion: a translation between two keys gives two steps at the shutter's ends") {
  ScratchDir dir("gltf-motion-translation");
  SceneDesc scene = with_shutter(dir, animated("translation", 0, {0, 1}, {0, 0, 0, 2, 0, 0}, "VEC3"), 0.5, -0.25, 0.25);
  const InstanceDesc& instance = scene.instances.at(0);
  REQUIRE(instance.motion.size() == 2);
  CHECK(x_translation(instance.motion[0]) == doctest::Approx(0.5));
  CHECK(x_translation(instance.motion[1]) == doctest::Approx(1.5));
  CHECK(x_translation(instance.transform) == doctest::Approx(1));  // the rendered time's pose
  CHECK(scene.cameras.at(0).motion.empty());
  CHECK(scene.meshes.at(0).motion_positions.empty());
  CHECK(analyze_effects(scene).has(effect_motion_blur));
}

TEST_CASE("gltf motion: keys inside the shutter add steps, capped at max_motion_steps") {
  ScratchDir dir("gltf-motion-keys");
  std::vector<float> times, values;
  for (int k = 0; k <= 40; ++k) times.push_back(0.1f * float(k)), values.insert(values.end(), {float(k % 2), 0, 0});
  SceneDesc few = with_shutter(dir, animated("translation", 0, times, values, "VEC3"), 1.0, -0.12, 0.12);
  CHECK(few.instances.at(0).motion.size() == 5);  // keys at 0.9, 1.0 and 1.1 inside: 4 stretches
  SceneDesc many = with_shutter(dir, animated("translation", 0, times, values, "VEC3"), 2.0, -1.5, 1.5);
  CHECK(many.instances.at(0).motion.size() == size_t(max_motion_steps));
}

TEST_CASE("gltf motion: a turning node, a morph and a moving camera become motion steps") {
  ScratchDir dir("gltf-motion-kinds");
  // A quarter turn about z from 0 to 1 s: a rotation's curve takes two intervals per stretch.
  SceneDesc turning = with_shutter(dir, animated("rotation", 0, {0, 1}, {0, 0, 0, 1, 0, 0, 0.7071068f, 0.7071068f}, "VEC4"),
                                   0.5, -0.5, 0.5);
  CHECK(turning.instances.at(0).motion.size() == 3);
  SceneDesc morphing = with_shutter(dir, animated("weights", 0, {0, 1}, {0, 1}, "SCALAR"), 0.5, -0.25, 0.25);
  const MeshDesc& mesh = morphing.meshes.at(size_t(morphing.instances.at(0).mesh));
  REQUIRE(mesh.motion_positions.size() == 2);
  CHECK(mesh.motion_positions[0].at(0).z == doctest::Approx(0.75));
  CHECK(mesh.motion_positions[1].at(0).z == doctest::Approx(2.25));
  CHECK(morphing.instances.at(0).motion.empty());
  SceneDesc panning = with_shutter(dir, animated("translation", 1, {0, 1}, {0, 0, 5, 4, 0, 5}, "VEC3"), 0.5, -0.25, 0.25);
  REQUIRE(panning.cameras.at(0).motion.size() == 2);
  CHECK(panning.cameras[0].motion[0].position.x == doctest::Approx(1));
  CHECK(panning.cameras[0].motion[1].position.x == doctest::Approx(3));
}

TEST_CASE("gltf motion: a shutter while nothing moves adds nothing and renders the unblurred image to the bit") {
  ScratchDir dir("gltf-motion-still");
  // The animation ends at 1 s; at 5 s nothing moves.
  std::string gltf = animated("translation", 0, {0, 1}, {0, 0, 0, 2, 0, 0}, "VEC3");
  SceneDesc scene = with_shutter(dir, gltf, 5, -0.5, 0.5);
  CHECK(scene.instances.at(0).motion.empty());
  CHECK_FALSE(analyze_effects(scene).has(effect_motion_blur));
  LoadOptions at_five;
  at_five.animation_time = 5;
  SceneDesc unblurred = load_scene(dir.write("still.gltf", gltf).string(), at_five);
  RenderOptions o;
  o.width = 24, o.height = 16, o.spp = 4, o.mode = RenderMode::path;
  RenderResult with = render_scene(scene, o), without = render_scene(unblurred, o);
  for (size_t i = 0; i < with.film.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) CHECK(with.film.pixels[i].sum[c] == without.film.pixels[i].sum[c]);
}

TEST_CASE("gltf motion: --shutter takes OPEN:CLOSE frames with OPEN below CLOSE") {
  ScratchDir dir("gltf-motion-flags");
  std::filesystem::path path = dir.write("moving.gltf", animated("translation", 0, {0, 1}, {0, 0, 0, 2, 0, 0}, "VEC3"));
  for (const char* bad : {"0.25", "0.25:-0.25", "a:b", "0:0"}) {
    CAPTURE(bad);
    CommandResult r = run_radiant("render " + quoted(path) + " -o " + quoted(dir.file("x.png")) +
                                  " --shutter=" + bad);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--shutter") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir.file("x.png")));
  }
}

TEST_CASE("gltf motion: radiant info names motion blur only when something moves while the shutter is open") {
  ScratchDir dir("gltf-motion-info");
  std::string path = quoted(dir.write("moving.gltf", animated("translation", 0, {0, 1}, {0, 0, 0, 2, 0, 0}, "VEC3")));
  CommandResult moving = run_radiant("info " + path + " --time 0.5 --shutter -6:6");
  REQUIRE(moving.exit_code == 0);
  CHECK(moving.out.find("motion-blur") != std::string::npos);
  CHECK(moving.out.find("1 moving instance(s)") != std::string::npos);
  CommandResult still = run_radiant("info " + path + " --time 5 --shutter -6:6");  // past the last key
  REQUIRE(still.exit_code == 0);
  CHECK(still.out.find("motion-blur") == std::string::npos);
  CommandResult sharp = run_radiant("info " + path + " --time 0.5");
  CHECK(sharp.out.find("motion-blur") == std::string::npos);
}
