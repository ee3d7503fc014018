// What the output files carry: AOV channels, and image-based environment light.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

namespace {


int channel(const TestImage& img, const std::string& name) {
  auto it = std::find(img.channel_names.begin(), img.channel_names.end(), name);
  REQUIRE(it != img.channel_names.end());
  return int(it - img.channel_names.begin());
}

// An equirectangular map, `width` x `width / 2`, radiance `sky` above the horizon and `ground` below.
fs::path write_environment(const ScratchDir& dir, int width, float sky, float ground) {
  int height = width / 2;
  std::vector<float> pixels(size_t(width) * height * 3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) pixels[(size_t(y) * width + x) * 3 + c] = y < height / 2 ? sky : ground;
  fs::path file = dir.file("sky.exr");
  write_test_image(file, width, height, {"R", "G", "B"}, pixels);
  return file;
}

const char* plane_scene =
    "@camera\nposition 0 4 0\ndirection 0 -1 0\nup 0 0 -1\northographic 2\n"
    "@plane\npoint 0 0 0\nnormal 0 1 0\nkd 0.25 0.5 0.75\n";

}  // namespace

TEST_CASE("output: --aov writes albedo, normal, depth, variance and spp channels named for compositing tools") {
  ScratchDir dir("aov");
  fs::path scene = dir.write("plane.scene", plane_scene);
  fs::path out = dir.file("aov.exr");
  REQUIRE(run_radiant("render " + quoted(scene) + " -o " + quoted(out) +
                      " --mode path --spp 8 --env-color 1,1,1 --width 4 --height 4 --aov albedo,normal,depth,variance,spp --quiet")
              .exit_code == 0);
  TestImage img = read_image(out);
  // EXR stores channels sorted by name; the set is what matters to compositing tools.
  std::vector<std::string> names = img.channel_names, expected = {"R", "G", "B", "albedo.R", "albedo.G", "albedo.B",
                                                                  "N.X", "N.Y", "N.Z", "Z", "variance.R", "variance.G",
                                                                  "variance.B", "spp"};
  std::sort(names.begin(), names.end());
  std::sort(expected.begin(), expected.end());
  CHECK(names == expected);
  CHECK(img.at(1, 2, channel(img, "albedo.G")) == doctest::Approx(0.5));
  CHECK(img.at(1, 2, channel(img, "N.Y")) == doctest::Approx(1.0));
  CHECK(img.at(1, 2, channel(img, "Z")) == doctest::Approx(4.0));
  CHECK(img.at(1, 2, channel(img, "spp")) == 8);
  CHECK(img.at(1, 2, channel(img, "variance.B")) >= 0);
  // The plane under a white sky reflects exactly its albedo (cosine-sampled sky, Lambertian).
  CHECK(img.at(1, 2, 2) == doctest::Approx(0.75).epsilon(0.01));
}

TEST_CASE("output: --aov and --half need an EXR file, also against a float HDR (usage error, nothing written)") {
  ScratchDir dir("aov-png");
  fs::path scene = dir.write("plane.scene", plane_scene);
  for (const char* name : {"x.png", "x.hdr"}) {
    CAPTURE(name);
    CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(dir.file(name)) + " --aov albedo");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--aov needs an EXR output") != std::string::npos);
    CHECK_FALSE(fs::exists(dir.file(name)));
  }
  CommandResult half = run_radiant("render " + quoted(scene) + " -o " + quoted(dir.file("y.hdr")) + " --half");
  CHECK(half.exit_code != 0);
  CHECK(half.err.find("--half needs an EXR output") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.file("y.hdr")));
}

TEST_CASE("output: an environment map lights the scene: a plane under a sky of 1 over a black ground shows its albedo") {
  ScratchDir dir("env-map");
  fs::path scene = dir.write("plane.scene", plane_scene);
  fs::path sky = write_environment(dir, 64, 1.0f, 0.0f);
  fs::path out = dir.file("lit.exr");
  REQUIRE(run_radiant("render " + quoted(scene) + " -o " + quoted(out) + " --env " + quoted(sky) +
                      " --mode path --spp 64 --width 4 --height 4 --quiet").exit_code == 0);
  TestImage img = read_image(out);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      CHECK(img.at(x, y, 0) == doctest::Approx(0.25).epsilon(0.03));
      CHECK(img.at(x, y, 2) == doctest::Approx(0.75).epsilon(0.03));
    }
  // Turned over, the plane faces the black ground and sees nothing.
  fs::path flipped = dir.write("flipped.scene",
                               "@camera\nposition 0 -4 0\ndirection 0 1 0\nup 0 0 -1\northographic 2\n"
                               "@plane\npoint 0 0 0\nnormal 0 -1 0\nkd 0.25 0.5 0.75\n");
  fs::path dark = dir.file("dark.exr");
  REQUIRE(run_radiant("render " + quoted(flipped) + " -o " + quoted(dark) + " --env " + quoted(sky) +
                      " --mode path --spp 16 --width 4 --height 4 --quiet").exit_code == 0);
  CHECK(read_image(dark).at(2, 2, 1) < 1e-3);
}

TEST_CASE("output: an unreadable environment map is an error naming the file") {
  ScratchDir dir("env-missing");
  fs::path scene = dir.write("plane.scene", plane_scene);
  CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(dir.file("x.exr")) + " --env " +
                                quoted(dir.file("nope.exr")) + " --mode path --quiet");
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("nope.exr") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.file("x.exr")));
}

TEST_CASE("output: an environment map with a non-finite pixel is refused naming the pixel") {
  ScratchDir dir("env-nonfinite");
  fs::path scene = dir.write("plane.scene", plane_scene);
  for (auto [bad, message] : {std::pair{std::nanf(""), "G is nan: environment radiance must be finite"},
                              {INFINITY, "G is inf: environment radiance must be finite"}}) {
    std::vector<float> pixels(4 * 2 * 3, 1.0f);
    pixels[(1 * 4 + 2) * 3 + 1] = bad;  // pixel (2, 1), G
    fs::path sky = dir.file("sky.exr");
    write_test_image(sky, 4, 2, {"R", "G", "B"}, pixels);
    CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(dir.file("x.exr")) + " --env " +
                                  quoted(sky) + " --mode path --width 4 --height 4 --spp 1 --quiet");
    CHECK(r.exit_code == 1);
    CHECK(r.err == "radiant: " + sky.string() + ": pixel (2, 1): " + message + "\n");
    CHECK_FALSE(fs::exists(dir.file("x.exr")));
  }
}

TEST_CASE("output: an environment map's tiny negative pixels read as 0, with one warning") {
  // Saved renders (Blender's world EXRs) carry values such as -1e-5.
  ScratchDir dir("env-negative");
  fs::path scene = dir.write("plane.scene", plane_scene);
  std::vector<float> pixels(4 * 2 * 3, 1.0f), clamped = pixels;
  pixels[(1 * 4 + 2) * 3 + 1] = -1.09e-5f, clamped[(1 * 4 + 2) * 3 + 1] = 0;
  pixels[(0 * 4 + 1) * 3 + 2] = -2e-6f, clamped[(0 * 4 + 1) * 3 + 2] = 0;
  write_test_image(dir.file("sky.exr"), 4, 2, {"R", "G", "B"}, pixels);
  write_test_image(dir.file("clamped.exr"), 4, 2, {"R", "G", "B"}, clamped);
  std::string flags = " --mode path --width 4 --height 4 --spp 4 --no-metadata";
  CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(dir.file("x.exr")) + " --env " +
                                quoted(dir.file("sky.exr")) + flags);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find("warning: " + dir.file("sky.exr").string() + ": 2 negative pixel value(s), down to -1.09e-05, read as 0") !=
        std::string::npos);
  REQUIRE(run_radiant("render " + quoted(scene) + " -o " + quoted(dir.file("y.exr")) + " --env " +
                      quoted(dir.file("clamped.exr")) + flags + " --quiet")
              .exit_code == 0);
  CHECK(same_pixels(dir.file("x.exr"), dir.file("y.exr")));  // the same as zeros
}
