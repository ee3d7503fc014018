// The flags that light and frame a model from the command line: --env names, --env-intensity,
// --background, --up, --orbit, and their usage errors.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>

#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

// A small grey sphere at the origin, no light, no camera.
constexpr const char* lone_sphere = "@sphere\ncenter 0 0 0\nradius 0.5\nkd 0.5\n";

// A 16x8 checkerboard map of 0 and 1 texels.
fs::path checker_map(const ScratchDir& dir) {
  std::vector<float> pixels(16 * 8 * 3);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x)
      for (int c = 0; c < 3; ++c) pixels[(size_t(y) * 16 + x) * 3 + c] = float((x + y) % 2);
  fs::path path = dir.file("checker.exr");
  write_test_image(path, 16, 8, {"R", "G", "B"}, pixels);
  return path;
}

}  // namespace

TEST_CASE("lighting flags: --background color shows the colour exactly where the camera sees nothing") {
  ScratchDir dir("background-color");
  fs::path scene = dir.write("s.scene", lone_sphere);
  REQUIRE(run_radiant("render " + quoted(scene) + " -o " + quoted(dir.file("o.exr")) +
                      " --width 16 --height 16 --spp 4 --orbit 0,0,4 --background color:0.25,0.5,0.75 -q")
              .exit_code == 0);
  TestImage image = read_image(dir.file("o.exr"));
  for (int c = 0; c < 3; ++c) CHECK(image.at(0, 0, c) == 0.25f * float(c + 1));
}

TEST_CASE("lighting flags: the default background blurs a map that --background env shows sharp") {
  ScratchDir dir("background-blur");
  fs::path scene = dir.write("s.scene", lone_sphere);
  fs::path map = checker_map(dir);
  std::string render = "render " + quoted(scene) + " --env " + quoted(map) +
                       " --camera-type equirect --width 32 --height 16 --spp 4 -q -o ";
  REQUIRE(run_radiant(render + quoted(dir.file("blur.exr"))).exit_code == 0);
  REQUIRE(run_radiant(render + quoted(dir.file("env.exr")) + " --background env").exit_code == 0);
  auto spread = [](const TestImage& image) {
    auto [low, high] = std::minmax_element(image.pixels.begin(), image.pixels.end());
    return *high - *low;
  };
  CHECK(spread(read_image(dir.file("env.exr"))) > 0.9f);
  CHECK(spread(read_image(dir.file("blur.exr"))) < 0.5f);
}

TEST_CASE("lighting flags: --env-intensity scales the whole image") {
  ScratchDir dir("env-intensity");
  fs::path scene = dir.write("s.scene", lone_sphere);
  std::string render = "render " + quoted(scene) + " --width 8 --height 8 --spp 8 -q -o ";
  REQUIRE(run_radiant(render + quoted(dir.file("one.exr"))).exit_code == 0);
  REQUIRE(run_radiant(render + quoted(dir.file("two.exr")) + " --env-intensity 2").exit_code == 0);
  TestImage one = read_image(dir.file("one.exr")), two = read_image(dir.file("two.exr"));
  REQUIRE(one.pixels.size() == two.pixels.size());
  for (size_t i = 0; i < one.pixels.size(); ++i)
    if (one.channel_names[i % one.channels] != "A") CHECK(two.pixels[i] == doctest::Approx(2 * one.pixels[i]).epsilon(1e-4));
}

TEST_CASE("lighting flags: bad values of --background, --up, --orbit and --env are usage errors naming the flag") {
  ScratchDir dir("lighting-usage");
  fs::path scene = dir.write("s.scene", lone_sphere);
  for (const char* flags : {"--background banana", "--background color:1,2", "--up +w", "--up 0,0,0", "--orbit 10",
                            "--orbit 10,20,0", "--orbit 10,nan", "--env-intensity -1", "--transparent --background env"}) {
    CAPTURE(flags);
    CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(dir.file("o.png")) + " " + flags);
    CHECK(r.exit_code == 2);
    std::string flag = std::string(flags).substr(0, std::string(flags).find(' '));
    if (flag == "--transparent") flag = "--background";
    CHECK(r.err.find(flag) != std::string::npos);
    CHECK_FALSE(fs::exists(dir.file("o.png")));
  }
}

TEST_CASE("lighting flags: --orbit with a named file camera is refused, --camera frame takes it") {
  ScratchDir dir("orbit-camera");
  fs::path scene = dir.write("s.scene", std::string("@camera\nposition 0 0 5\ndirection 0 0 -1\nup 0 1 0\n") + lone_sphere);
  std::string render = "render " + quoted(scene) + " -o " + quoted(dir.file("o.png")) + " --width 8 --height 8 --spp 1 -q";
  CommandResult named = run_radiant(render + " --camera 0 --orbit 30,10");
  CHECK(named.exit_code != 0);
  CHECK(named.err.find("--orbit turns the framing camera") != std::string::npos);
  CHECK(run_radiant(render + " --camera frame --orbit 30,10").exit_code == 0);
  CHECK(run_radiant(render + " --up +Z").exit_code == 0);
}
