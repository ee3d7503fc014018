// Temporaries are created exclusively under names nobody can guess: a symlink planted where a
// temporary might go is never followed, so radiant cannot be made to overwrite its target.
#include <doctest/doctest.h>

#include <filesystem>

#include "support/child_process.h"
#include "support/test_scenes.h"

using namespace radiant::test;
namespace fs = std::filesystem;

TEST_CASE("temporary files: symlinks planted at the temporaries' old predictable names are never followed") {
  ScratchDir dir("tmp-symlink");
  fs::path scene = dir.write("plane.scene", lit_plane_scene);
  fs::path victim = dir.write("victim.txt", "not radiant's to write");
  RadiantProcess child({"render", scene, "-o", dir.file("out.png"), "--stats", dir.file("stats.json"), "--width", "32",
                        "--height", "32", "--spp", "16", "--quiet"});
  // Planted as soon as the process id is known, long before the render ends.
  std::string pid = std::to_string(child.pid());
  fs::create_symlink(victim, dir.file(".out.tmp-" + pid + ".png"));
  fs::create_symlink(victim, dir.file("stats.json.tmp-" + pid));
  CommandResult r = child.wait(60);
  CHECK(r.exit_code == 0);
  CHECK(read_bytes(victim) == "not radiant's to write");
  CHECK(read_image(dir.file("out.png")).width == 32);
  CHECK(read_bytes(dir.file("stats.json")).find("\"width\": 32") != std::string::npos);
}
