// --camera-type, --lens-radius, --focus-distance and --blades from the command line and the
// `.scene` camera: they render, and their misuse is one line, exit 2 (exit 1 in a file), no image.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>

#include "support/test_scenes.h"
#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

TEST_CASE("camera flags: panoramas and a lens render, their default image shapes follow the projection") {
  ScratchDir dir("camera-flags");
  fs::path scene = dir.write("s.scene", lit_sphere_scene);
  struct Case {
    std::string flags;
    int width, height;
  };
  for (const Case& c : {Case{"--camera-type equirect --height 8", 16, 8}, Case{"--camera-type fisheye --fov 200 --width 8", 8, 8},
                        Case{"--look-from 0,0,5 --look-at 0,0,0 --lens-radius 0.2 --blades 6 --width 8 --height 6", 8, 6}}) {
    CAPTURE(c.flags);
    fs::path out = dir.file("out.exr");
    CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(out) + " --spp 2 --quiet " + c.flags);
    CAPTURE(r.err);
    REQUIRE(r.exit_code == 0);
    TestImage image = read_image(out);
    CHECK(image.width == c.width);
    CHECK(image.height == c.height);
    fs::remove(out);
  }
}

TEST_CASE("camera flags: a lens without focus, a lens on a panorama, bad types and blade counts are usage errors") {
  ScratchDir dir("camera-flag-errors");
  fs::path scene = dir.write("s.scene", lit_sphere_scene);
  fs::path out = dir.file("out.png");
  struct Case {
    std::string flags, message;
  };
  for (const Case& c :
       {Case{"--lens-radius 0.1", "a lens (--lens-radius) needs a focus distance: --focus-distance D, or --look-at"},
        Case{"--lens-radius 0.1 --focus-distance 3 --camera-type fisheye",
             "a lens (--lens-radius) needs a perspective or orthographic camera"},
        Case{"--camera-type spherical", "unknown camera type 'spherical' (expected "
                                        "perspective, orthographic, equirect or fisheye)"},
        Case{"--blades 2", "an aperture needs 0 (round) or at least 3 blades"},
        Case{"--camera-type equirect --fov 90",
             "--fov does not apply to an equirectangular camera (it sees all around)"},
        Case{"--focus-distance -1", "--focus-distance"}}) {
    CAPTURE(c.flags);
    CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(out) + " --width 4 --height 4 --spp 1 " + c.flags);
    CHECK(r.exit_code == 2);
    CHECK(r.err.rfind("radiant render: ", 0) == 0);
    CHECK(r.err.find(c.message) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(fs::exists(out));
  }
}

TEST_CASE("camera flags: the .scene camera's lens attributes, and their errors at file:line:col") {
  ScratchDir dir("scene-lens");
  fs::path out = dir.file("out.exr");
  std::string camera = "@camera\nposition 0 0 5\nlook-at 0 0 0\n";
  fs::path good = dir.write("lens.scene", camera + "lens-radius 0.2\nblades 5\n" + lit_sphere_scene);
  CommandResult r = run_radiant("render " + quoted(good) + " -o " + quoted(out) + " --width 8 --height 8 --spp 2 --quiet");
  CAPTURE(r.err);
  CHECK(r.exit_code == 0);
  fs::path unfocused = dir.write("unfocused.scene", "@camera\nposition 0 0 5\ndirection 0 0 -1\nlens-radius 0.2\n" +
                                                        std::string(lit_sphere_scene));
  r = run_radiant("render " + quoted(unfocused) + " -o " + quoted(dir.file("u.exr")) + " --spp 1 --quiet");
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("unfocused.scene:4:1: 'lens-radius' needs 'focus-distance' or 'look-at' to focus on\n") !=
        std::string::npos);
  fs::path two_blades = dir.write("blades.scene", camera + "lens-radius 0.2\nblades 2\n" + lit_sphere_scene);
  r = run_radiant("render " + quoted(two_blades) + " -o " + quoted(dir.file("b.exr")) + " --spp 1 --quiet");
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("blades.scene:5:8: 'blades' must be 0 (a round aperture) or 3 to 64\n") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.file("u.exr")));
  CHECK_FALSE(fs::exists(dir.file("b.exr")));
}

TEST_CASE("camera flags: the .scene camera's panorama attribute sets the projection and the image shape") {
  ScratchDir dir("scene-panorama");
  fs::path equirect = dir.write("e.scene", "@camera\nposition 0 0 5\ndirection 0 0 -1\npanorama equirect\n" +
                                              std::string(lit_sphere_scene));
  CommandResult r = run_radiant("render " + quoted(equirect) + " -o " + quoted(dir.file("e.exr")) + " --height 4 --spp 1 --quiet");
  CAPTURE(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(read_image(dir.file("e.exr")).width == 8);
  fs::path fisheye = dir.write("f.scene", "@camera\nposition 0 0 5\ndirection 0 0 -1\npanorama fisheye\nfisheye-fov 220\n" +
                                             std::string(lit_sphere_scene));
  r = run_radiant("render " + quoted(fisheye) + " -o " + quoted(dir.file("f.exr")) + " --height 6 --spp 1 --quiet");
  REQUIRE(r.exit_code == 0);
  CHECK(read_image(dir.file("f.exr")).width == 6);
  // The equirect camera's own 2:1 resolution does not follow it into --camera-type fisheye.
  fs::path sized = dir.write("s.scene", "@camera\nposition 0 0 5\ndirection 0 0 -1\npanorama equirect\nresolution 16 8\n" +
                                           std::string(lit_sphere_scene));
  r = run_radiant("render " + quoted(sized) + " -o " + quoted(dir.file("s.exr")) + " --camera-type fisheye --width 6 --spp 1 --quiet");
  REQUIRE(r.exit_code == 0);
  CHECK(read_image(dir.file("s.exr")).height == 6);
  fs::path bad = dir.write("bad.scene", "@camera\nposition 0 0 5\ndirection 0 0 -1\nfisheye-fov 90\n" + std::string(lit_sphere_scene));
  r = run_radiant("render " + quoted(bad) + " -o " + quoted(dir.file("b.exr")) + " --spp 1 --quiet");
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("bad.scene:4:1: 'fisheye-fov' needs 'panorama fisheye'\n") != std::string::npos);
  fs::path mixed = dir.write("mixed.scene", "@camera\nposition 0 0 5\ndirection 0 0 -1\nfov 40\npanorama equirect\n" +
                                               std::string(lit_sphere_scene));
  r = run_radiant("render " + quoted(mixed) + " -o " + quoted(dir.file("m.exr")) + " --spp 1 --quiet");
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("mixed.scene:5:1: 'panorama' cannot be combined with 'fov'\n") != std::string::npos);
}

namespace {

// The share of pixels where something other than the black background is seen.
double lit_share(const TestImage& image) {
  int lit = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (image.at(x, y, 0) + image.at(x, y, 1) + image.at(x, y, 2) > 0) ++lit;
  return double(lit) / (image.width * image.height);
}

}  // namespace

TEST_CASE("camera flags: --camera-type orthographic frames the scene, and --ortho-height sets the view's height") {
  ScratchDir dir("ortho-framing");
  std::string common = "render " + quoted(source_path("assets/cornell.gltf")) + " --width 32 --height 32 --spp 4 --quiet --env none ";
  CommandResult framed = run_radiant(common + "-o " + quoted(dir.file("framed.exr")) + " --camera-type orthographic");
  REQUIRE(framed.exit_code == 0);
  // Seen face on, the open box fills the frame but for the 5% margin (the view was 2 m tall for a 0.55 m box).
  double framed_share = lit_share(read_image(dir.file("framed.exr")));
  CHECK(framed_share > 0.75);
  CommandResult tall = run_radiant(common + "-o " + quoted(dir.file("tall.exr")) + " --camera-type orthographic --ortho-height 2.2");
  REQUIRE(tall.exit_code == 0);
  double tall_share = lit_share(read_image(dir.file("tall.exr")));
  CHECK(tall_share < 0.1);  // a 0.55 m box in a 2.2 m view: a sixteenth of it
  CHECK(tall_share > 0.02);
  CommandResult perspective = run_radiant(common + "-o " + quoted(dir.file("p.exr")) + " --ortho-height 2");
  CHECK(perspective.exit_code == 2);
  CHECK(perspective.err.find("--ortho-height") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.file("p.exr")));
}
