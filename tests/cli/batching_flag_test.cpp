// --batching chooses how paths share their ray tracing; each choice writes the same PNG, and an
// unknown one is a usage error naming the choices.
#include <doctest/doctest.h>

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
