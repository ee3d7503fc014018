// --batching chooses how paths share their ray tracing; each choice writes the same PNG, and an
// unknown one is a usage error naming the choices.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

TEST_CASE("render cli: --batching none, camera and all give the same pixels for the glTF Cornell box") {
  ScratchDir dir("cli-batching");
  std::vector<float> images[3];
  const char* choices[3] = {"none", "camera", "all"};
  for (int i = 0; i < 3; ++i) {
    fs::path out = dir.file(std::string(choices[i]) + ".png");
    CommandResult r = run_radiant("render " + quoted(source_path("assets/cornell.gltf")) + " -o " + quoted(out) +
                                  " --width 24 --height 20 --spp 4 --mode path --quiet --batching " + choices[i]);
    REQUIRE(r.exit_code == 0);
    images[i] = read_image(out).pixels;  // the files differ in the command line they record
  }
  CHECK(images[0].size() == 24 * 20 * 3);
  CHECK(images[1] == images[0]);
  CHECK(images[2] == images[0]);
}

TEST_CASE("render cli: an unknown --batching is a usage error naming the choices") {
  ScratchDir dir("cli-batching-bad");
  fs::path out = dir.file("out.png");
  CommandResult r = run_radiant("render " + quoted(source_path("assets/first-render.scene")) + " -o " + quoted(out) +
                                " --batching simd");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("unknown batching 'simd' (expected none, camera or all)") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("render cli: --indirect-paths is reported, and refused for Whitted and outside [1, 64]") {
  ScratchDir dir("cli-indirect-paths");
  fs::path out = dir.file("out.png"), stats = dir.file("stats.json");
  std::string render = "render " + quoted(source_path("assets/cornell.gltf")) + " -o " + quoted(out) +
                       " --width 12 --height 10 --spp 2 --quiet";
  CommandResult ok = run_radiant(render + " --indirect-paths 3 --stats " + quoted(stats));
  REQUIRE(ok.exit_code == 0);
  CHECK(read_bytes(stats).find("\"indirect_paths\": 3") != std::string::npos);
  fs::remove(out);
  for (const char* bad : {" --mode whitted --indirect-paths 2", " --indirect-paths 0", " --indirect-paths 65"}) {
    CAPTURE(bad);
    CommandResult r = run_radiant(render + bad);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--indirect-paths") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(fs::exists(out));
  }
}
