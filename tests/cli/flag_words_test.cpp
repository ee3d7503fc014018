// What CLI11 does not check for us: flags given twice, and typos with suggestions.
#include <doctest/doctest.h>

#include <filesystem>

#include "support/test_scenes.h"
#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

TEST_CASE("flags: a typo is a usage error suggesting the nearest flags, and nothing is written") {
  ScratchDir dir("flag-typo");
  fs::path scene = dir.write("s.scene", lit_plane_scene);
  std::string render = "render " + quoted(scene) + " -o " + quoted(dir.file("o.png"));
  CommandResult r = run_radiant(render + " --sampels 4");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("--sampels: unknown flag; did you mean --sampler or --spp?") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.file("o.png")));
  r = run_radiant(render + " --widht=8");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("did you mean --width?") != std::string::npos);
  r = run_radiant("info " + quoted(scene) + " --jsno");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("did you mean --json?") != std::string::npos);
  r = run_radiant(render + " --zzzzzzzz 1");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("--zzzzzzzz: unknown flag (--help lists them)") != std::string::npos);
}

TEST_CASE("flags: a flag given twice is a usage error naming both, in every form") {
  ScratchDir dir("flag-twice");
  fs::path scene = dir.write("s.scene", lit_plane_scene);
  std::string render = "render " + quoted(scene) + " -o " + quoted(dir.file("o.png"));
  CommandResult r = run_radiant(render + " --spp 4 --spp=8");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("--spp: given twice (--spp and --spp=8)") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.file("o.png")));
  r = run_radiant(render + " -o " + quoted(dir.file("p.png")));
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("given twice (-o and -o)") != std::string::npos);
  // Values that look like flags are values.
  r = run_radiant(render + " --width 8 --height 8 --spp 1 --look-from -1,4,0 --look-at -1,0,0 --up 0,0,-1");
  CHECK(r.exit_code == 0);
  fs::path script = dir.write("views.txt", "scene s.scene\nrender -o a.png --spp 1 --spp 2\n");
  r = run_radiant("batch " + quoted(script));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("views.txt:2: --spp: given twice (--spp and --spp)") != std::string::npos);
}

TEST_CASE("help: every command's --help shows examples and exits 0") {
  for (const char* command : {"render", "info", "compare", "converge", "batch", "session"}) {
    CommandResult r = run_radiant(std::string(command) + " --help");
    CHECK_MESSAGE(r.exit_code == 0, command);
    CHECK_MESSAGE(r.out.find("Examples:") != std::string::npos, command);
    CHECK_MESSAGE(r.out.find(std::string("radiant ") + command) != std::string::npos, command);
  }
}
