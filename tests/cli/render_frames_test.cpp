// `render --frames A-B`: many frames of an animation in one process, the file read once, each
// frame the image a separate `render --frame N` gives, the noise changing from frame to frame.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include "loaders/gltf_builder.h"
#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

// A triangle that slides along x from -0.5 at 0 s to +0.5 at 1 s (or stays, when `still`), seen
// by a camera at z = 3.
std::string sliding_triangle(bool still = false) {
  GltfBuilder b;
  b.floats({-0.5f, -0.5f, 0, 0.5f, -0.5f, 0, 0, 0.5f, 0}, "VEC3", 3);
  int input = b.floats({0, 1}, "SCALAR", 1);
  int output = b.floats({-0.5f, 0, 0, still ? -0.5f : 0.5f, 0, 0}, "VEC3", 3);
  return b.gltf("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],"
                "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.8,\"znear\":0.1}}],"
                "\"nodes\":[{\"mesh\":0},{\"camera\":0,\"translation\":[0,0,3]}],\"scenes\":[{\"nodes\":[0,1]}],"
                "\"scene\":0,\"animations\":[{\"channels\":[{\"sampler\":0,\"target\":{\"node\":0,\"path\":\"translation\"}}],"
                "\"samplers\":[{\"input\":" + std::to_string(input) + ",\"output\":" + std::to_string(output) + "}]}]");
}

const std::string noisy = " --width 16 --height 16 --spp 2 --mode path --env-color 1,1,1 --fps 4";

// Whether `image` has the pixels of a separate `render --frame N` of `scene`.
bool is_separate_render(const ScratchDir& dir, const fs::path& scene, int frame, const std::string& image) {
  std::string alone = "alone-" + std::to_string(frame) + ".png";
  CommandResult single = run_radiant("render " + quoted(scene) + noisy + " --quiet --frame " + std::to_string(frame) +
                                     " -o " + quoted(dir.file(alone)));
  return single.exit_code == 0 && same_pixels(dir.file(alone), dir.file(image));
}

size_t count_of(const std::string& text, const std::string& part) {
  size_t count = 0;
  for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
  return count;
}

}  // namespace

TEST_CASE("render --frames: the file is read once and frame N is the image of a separate render --frame N") {
  ScratchDir dir("render-frames");
  fs::path scene = dir.write("slide.gltf", sliding_triangle());
  CommandResult run = run_radiant("render " + quoted(scene) + noisy + " --frames 1-3 -o " + quoted(dir.file("f-##.png")) +
                                  " --stats " + quoted(dir.file("stats-#.json")));
  REQUIRE(run.exit_code == 0);
  CHECK(count_of(run.err, "radiant: read ") == 1);
  CHECK_FALSE(fs::exists(dir.file("f-00.png")));
  for (int frame = 1; frame <= 3; ++frame) {
    std::string name = "f-0" + std::to_string(frame) + ".png";
    REQUIRE(fs::exists(dir.file(name)));
    nlohmann::json stats = nlohmann::json::parse(read_bytes(dir.file("stats-" + std::to_string(frame) + ".json")));
    CHECK(stats["frame"]["number"] == frame);
    CHECK(stats["frame"]["scene_reads"] == 1);
    CHECK(stats["frame"]["accelerator"] == (frame == 1 ? "built" : "updated"));  // from the frame before
    CHECK(stats["output"] == dir.file(name).string());
  }
  CHECK(!same_pixels(dir.file("f-01.png"), dir.file("f-03.png")));  // the triangle moved
  CommandResult alone = run_radiant("render " + quoted(scene) + noisy + " --frame 2 -o " + quoted(dir.file("alone.png")));
  REQUIRE(alone.exit_code == 0);
  CHECK(same_pixels(dir.file("alone.png"), dir.file("f-02.png")));
}

TEST_CASE("render --frames: a floor, a morphing and a turning triangle update the accelerator, each frame is a separate render's") {
  GltfBuilder b;
  b.floats({-2, -1, -2, 2, -1, -2, 2, -1, 2, -2, -1, 2}, "VEC3", 3);  // 0: floor
  b.floats({-0.5f, -0.5f, 0, 0.5f, -0.5f, 0, 0, 0.5f, 0}, "VEC3", 3);  // 1: triangle
  b.floats({0, 0, 0, 0, 0, 0, 0, 0.7f, 0.3f}, "VEC3", 3);               // 2: morph target: the tip rises
  int times = b.floats({0, 1}, "SCALAR", 1);
  int weights = b.floats({0, 1}, "SCALAR", 1);
  int turns = b.floats({0, 0, 0, 1, 0, 0.7071068f, 0, 0.7071068f}, "VEC4", 4);
  std::string gltf = b.gltf(
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":" + std::to_string(b.indices({0, 2, 1, 0, 3, 2})) +
      "}]},{\"primitives\":[{\"attributes\":{\"POSITION\":1},\"targets\":[{\"POSITION\":2}]}]},"
      "{\"primitives\":[{\"attributes\":{\"POSITION\":1}}]}],"
      "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.9,\"znear\":0.1}}],"
      "\"nodes\":[{\"mesh\":0},{\"mesh\":1,\"translation\":[-0.6,0,0]},{\"mesh\":2,\"translation\":[0.6,0,0]},"
      "{\"camera\":0,\"translation\":[0,0.5,4]}],\"scenes\":[{\"nodes\":[0,1,2,3]}],\"scene\":0,"
      "\"animations\":[{\"channels\":[{\"sampler\":0,\"target\":{\"node\":1,\"path\":\"weights\"}},"
      "{\"sampler\":1,\"target\":{\"node\":2,\"path\":\"rotation\"}}],"
      "\"samplers\":[{\"input\":" + std::to_string(times) + ",\"output\":" + std::to_string(weights) + "},"
      "{\"input\":" + std::to_string(times) + ",\"output\":" + std::to_string(turns) + "}]}]");
  ScratchDir dir("render-frames-deform");
  fs::path scene = dir.write("deform.gltf", gltf);
  CommandResult run = run_radiant("render " + quoted(scene) + noisy + " --quiet --frames 0-3 -o " + quoted(dir.file("f-#.png")) +
                                  " --stats " + quoted(dir.file("s-#.json")));
  REQUIRE(run.exit_code == 0);
  for (int frame = 0; frame <= 3; ++frame) {
    nlohmann::json stats = nlohmann::json::parse(read_bytes(dir.file("s-" + std::to_string(frame) + ".json")));
    CHECK(stats["frame"]["accelerator"] == (frame == 0 ? "built" : "updated"));
    CHECK(is_separate_render(dir, scene, frame, "f-" + std::to_string(frame) + ".png"));
  }
  CHECK(!same_pixels(dir.file("f-1.png"), dir.file("f-3.png")));
}

TEST_CASE("render --frames: the noise changes from frame to frame unless --same-noise") {
  ScratchDir dir("render-frames-noise");
  fs::path scene = dir.write("still.gltf", sliding_triangle(true));
  CommandResult animated = run_radiant("render " + quoted(scene) + noisy + " --quiet --frames 0-1 -o " + quoted(dir.file("a-#.png")));
  CommandResult same = run_radiant("render " + quoted(scene) + noisy + " --quiet --same-noise --frames 0-1 -o " +
                                   quoted(dir.file("s-#.png")));
  REQUIRE(animated.exit_code == 0);
  REQUIRE(same.exit_code == 0);
  CHECK(!same_pixels(dir.file("a-0.png"), dir.file("a-1.png")));
  CHECK(same_pixels(dir.file("s-0.png"), dir.file("s-1.png")));
  // --same-noise renders with --seed itself: the frame is the image of --time with that seed.
  CommandResult by_time = run_radiant("render " + quoted(scene) + " --width 16 --height 16 --spp 2 --mode path "
                                      "--env-color 1,1,1 --quiet --time 0.25 -o " + quoted(dir.file("t.png")));
  REQUIRE(by_time.exit_code == 0);
  CHECK(same_pixels(dir.file("t.png"), dir.file("s-1.png")));
}

TEST_CASE("render --frames: usage errors exit 2, and a failing frame is named while the frames before it stay") {
  ScratchDir dir("render-frames-errors");
  fs::path scene = dir.write("slide.gltf", sliding_triangle());
  CommandResult no_run = run_radiant("render " + quoted(scene) + noisy + " --frames 0-2 -o " + quoted(dir.file("out.png")));
  CHECK(no_run.exit_code == 2);
  CHECK(no_run.err.find("-o needs a run of # for the frame number") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.file("out.png")));
  CommandResult sharded = run_radiant("render " + quoted(scene) + noisy + " --frames 0-2 --shard 0/2 -o " +
                                      quoted(dir.file("s-#.exr")));
  CHECK(sharded.exit_code == 2);
  CHECK(sharded.err.find("cannot be combined with --shard") != std::string::npos);
  CommandResult both = run_radiant("render " + quoted(scene) + noisy + " --frames 0-2 --frame 1 -o " + quoted(dir.file("b-#.png")));
  CHECK(both.exit_code == 2);
  CommandResult backwards = run_radiant("render " + quoted(scene) + noisy + " --frames 3-1 -o " + quoted(dir.file("b-#.png")));
  CHECK(backwards.exit_code == 2);
  CHECK(backwards.err.find("--frames: the first frame comes after the last in '3-1'") != std::string::npos);
  // Frames 0 and 1 go to folders that exist; frame 2's folder does not.
  fs::create_directory(dir.file("out-0"));
  fs::create_directory(dir.file("out-1"));
  CommandResult failing = run_radiant("render " + quoted(scene) + noisy + " --quiet --frames 0-2 -o " +
                                      quoted(dir.file("out-#") / "image.png"));
  CHECK(failing.exit_code == 1);
  CHECK(failing.err.rfind("radiant: frame 2: ", 0) == 0);
  CHECK(fs::exists(dir.file("out-0") / "image.png"));
  CHECK(fs::exists(dir.file("out-1") / "image.png"));
}

TEST_CASE("batch: render lines at frames of their own reuse the scene file, read once") {
  ScratchDir dir("batch-frames");
  fs::path scene = dir.write("slide.gltf", sliding_triangle());
  fs::path script = dir.write("frames.txt", "scene slide.gltf\n"
                                            "render -o b1.png --frame 1 --stats s1.json" + noisy + "\n"
                                            "render -o b3.png --frame 3 --stats s3.json" + noisy + "\n");
  CommandResult batch = run_radiant("batch " + quoted(script) + " --quiet");
  REQUIRE(batch.exit_code == 0);
  for (int frame : {1, 3}) {
    nlohmann::json stats = nlohmann::json::parse(read_bytes(dir.file("s" + std::to_string(frame) + ".json")));
    CHECK(stats["frame"]["number"] == frame);
    CHECK(stats["frame"]["scene_reads"] == 1);
    CHECK(stats["frame"]["accelerator"] == (frame == 1 ? "built" : "updated"));
  }
  for (int frame : {1, 3}) CHECK(is_separate_render(dir, scene, frame, "b" + std::to_string(frame) + ".png"));
  CHECK(!same_pixels(dir.file("b1.png"), dir.file("b3.png")));
  fs::path many = dir.write("many.txt", "scene slide.gltf\nrender -o m.png --frames 0-2" + noisy + "\n");
  CommandResult refused = run_radiant("batch " + quoted(many));
  CHECK(refused.exit_code == 1);
  CHECK(refused.err.find("give one render line per frame") != std::string::npos);
}
