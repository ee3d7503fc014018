// Numeric flags take finite numbers in the type they are stored in: NaN passes CLI11's Range and
// PositiveNumber, and 1e39 is finite as a double but infinite in a float.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>

#include "support/test_scenes.h"
#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

TEST_CASE("numeric flags: render refuses NaN, infinities and float overflow, naming the flag") {
  ScratchDir dir("numeric-flags");
  fs::path scene = dir.write("s.scene", lit_sphere_scene);
  fs::path out = dir.file("out.exr");
  for (std::string flag : {"--noise-threshold nan", "--noise-threshold inf", "--noise-threshold 1e39",
                           "--noise-threshold -nan", "--env-color 1e39,0,0", "--env-color 1,nan,1",
                           "--look-from 1e39,0,0", "--look-at 0,0,-1e39", "--up 0,inf,0", "--fov nan",
                           "--fov 1e39"}) {
    CAPTURE(flag);
    CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(out) +
                                  " --width 4 --height 4 --spp 1 --quiet " + flag);
    CHECK(r.exit_code == 2);
    CHECK(r.err.rfind("radiant render: " + flag.substr(0, flag.find(' ')) + ": ", 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(fs::exists(out));
  }
}

TEST_CASE("numeric flags: converge refuses NaN for --target-error and --edge-fraction") {
  ScratchDir dir("numeric-converge");
  fs::path scene = dir.write("s.scene", lit_sphere_scene);
  for (std::string flag : {"--target-error nan", "--edge-fraction nan", "--target-error 1e39"}) {
    CAPTURE(flag);
    CommandResult r = run_radiant("converge " + quoted(scene) + " --out " + quoted(dir.path) + " " + flag);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(flag.substr(0, flag.find(' ')) + ": ") != std::string::npos);
  }
}

TEST_CASE("numeric flags: a batch line with a NaN noise threshold is refused as script:line") {
  ScratchDir dir("numeric-batch");
  dir.write("s.scene", lit_sphere_scene);
  fs::path script = dir.write("views.txt", "scene s.scene\nrender -o a.png --spp 1 --noise-threshold nan\n");
  CommandResult r = run_radiant("batch " + quoted(script));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("views.txt:2: --noise-threshold: ") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.file("a.png")));
}
