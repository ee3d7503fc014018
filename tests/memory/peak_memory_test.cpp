// The cap holds in fact, not only in the budget's arithmetic: radiant runs on hostile files under
// --max-memory 64 MiB in a child process whose peak resident memory (wait4's rusage) must stay
// under the cap plus the process's own baseline (the binary, TBB, Embree and, when it is loaded,
// the OpenImageIO module, measured here on an 8x8 render) plus a small slack.
#include <doctest/doctest.h>

#include <filesystem>

#include "support/hostile_files.h"
#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

constexpr uint64_t MiB = uint64_t(1) << 20;
constexpr uint64_t cap = 64 * MiB;
constexpr const char* cap_flag = " --max-memory 0.0625";
// What the child may use above the cap and its baseline: allocator slack and small buffers that
// are not charged (messages, paths, the stacks of TBB's threads).
constexpr uint64_t slack = 16 * MiB;
// Keeps a regression from taking the machine down with it; far above every bound checked here.
constexpr uint64_t address_space_limit = uint64_t(4) << 30;


MeasuredRun measure(const std::string& args) {
  return run_radiant_measured(args, 120, built_with_address_sanitizer ? 0 : address_space_limit);
}

// Peak memory of an 8x8 render of a tiny scene written to `output` (a PNG or EXR needs no
// OpenImageIO, a TIFF loads it).
uint64_t baseline(const ScratchDir& dir, const std::string& output) {
  MeasuredRun run = measure("render " + quoted(source_path("assets/first-render.scene")) + " -o " +
                            quoted(dir.file(output)) + " --width 8 --height 8 --spp 1 -q");
  REQUIRE(run.result.exit_code == 0);
  // A baseline this large would hide what the cap is for (the sanitizer's own memory aside).
  if (!built_with_address_sanitizer) CHECK(run.peak_rss_bytes < 200 * MiB);
  return run.peak_rss_bytes;
}

struct HostileCase {
  std::string name;
  std::string args;              // after "render SCENE"
  std::string expected_message;  // part of stderr when refused; empty: must render within the cap
  bool loads_image_module = false;
};

}  // namespace

TEST_CASE("peak memory: hostile files under --max-memory stay within the cap plus the process's baseline") {
  ScratchDir dir("peak-memory");
  dir.write("sparse.gltf", sparse_positions_gltf(80000000));
  dir.write("sparse-near-cap.gltf", sparse_positions_gltf(2500000));  // 57 MiB charged, then refused
  dir.write("extras.gltf", gltf_with_extras(5000000));
  dir.write("many.mtl", mtl_with_materials(1000000));
  dir.write("many.obj", obj_using_mtl("many.mtl"));
  dir.write("faces.obj", obj_with_faces(2000000));
  dir.write("big.jpg", truncated_jpeg(dir.path, 8000, 8000));
  dir.write("image.gltf", gltf_textured_triangle("big.jpg"));
  std::string mtl;
  dir.write("texture.obj", obj_textured_triangle("texture.mtl", "big.jpg", mtl));
  dir.write("texture.mtl", mtl);
  dir.write("sky.hdr", hdr_header_only(20000, 10000));
  dir.write("words.scene", scene_with_words(10, 500000));  // 10 MB of text, 240 MB of tokens
  std::string env = " --env-color 1,1,1 --width 8 --height 8 --spp 1";
  std::string over = "over the memory limit of 64.0 MiB (--max-memory)";
  std::vector<HostileCase> cases = {
      {"sparse.gltf", env + " -o out.png", over},
      {"sparse-near-cap.gltf", env + " -o out.png", over},
      {"extras.gltf", env + " -o out.png", over},
      {"many.obj", env + " -o out.png", over},
      {"faces.obj", env + " -o out.png", over},
      {"image.gltf", env + " -o out.png", over},
      {"words.scene", env + " -o out.png", over},
      {"texture.obj", env + " -o out.png", over, true},
      {"first-render.scene", " --width 8 --height 8 --spp 1 --mode path -o out.png --env " + quoted(dir.file("sky.hdr")),
       over, true},
      {"first-render.scene", " --width 4096 --height 4096 --spp 1 -o out.exr --aov albedo,normal,depth,variance,spp",
       over},
      // Renders that fit: the film and image charges must cover what the render really takes.
      {"first-render.scene", " --width 600 --height 600 --spp 1 -o out.png", ""},
      // 450x450: exact AOV sums take 104 bytes a pixel more than double sums did (292 bytes in all).
      {"first-render.scene", " --width 450 --height 450 --spp 1 -o out.exr --aov albedo,normal,depth,variance,spp", ""},
      {"cornell.gltf", " --width 128 --height 128 --spp 1 -o out.exr --aov albedo,normal,depth,variance,spp", ""},
  };
  uint64_t without_module = baseline(dir, "baseline.png"), with_module = baseline(dir, "baseline.tif");
  for (const HostileCase& c : cases) {
    CAPTURE(c.name);
    CAPTURE(c.args);
    fs::path scene = c.name == "first-render.scene" ? source_path("assets/first-render.scene")
                     : c.name == "cornell.gltf"     ? source_path("assets/cornell.gltf")
                                                    : dir.file(c.name);
    std::string args = c.args;
    args.replace(args.find(" -o ") + 4, 0, dir.path.string() + "/");
    MeasuredRun run = measure("render " + quoted(scene) + args + cap_flag + " -q");
    CAPTURE(run.result.err);
    if (c.expected_message.empty()) {
      CHECK(run.result.exit_code == 0);
    } else {
      CHECK(run.result.exit_code == 1);
      CHECK(run.result.err.find(c.expected_message) != std::string::npos);
    }
    if (built_with_address_sanitizer) continue;  // resident memory there is the sanitizer's
    uint64_t bound = cap + (c.loads_image_module ? with_module : without_module) + slack;
    CAPTURE(run.peak_rss_bytes / MiB);
    CAPTURE(bound / MiB);
    CHECK(run.peak_rss_bytes <= bound);
  }
}
