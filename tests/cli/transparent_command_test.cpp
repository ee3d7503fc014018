// `render --transparent`: EXR stores associated (premultiplied) RGBA, PNG and TIFF straight alpha;
// shards carry the coverage sums and merge to the single render's bits.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>

#include "image/image_writer.h"
#include "support/radiant_ok.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

// The glowing sphere on an empty background, with a grey sky a transparent render must not show.
// The standard view: the scene asks for the linear one, which merge does not know of.
const std::string sphere_flags = " --width 24 --height 24 --spp 16 --env-color 0.5,0.5,0.5 --view standard --quiet";

std::string sphere() { return quoted(source_path("assets/first-render.scene")); }

}  // namespace

TEST_CASE("transparent cli: PNG holds straight alpha, the EXR's premultiplied color divided by its alpha, encoded") {
  ScratchDir dir("transparent-formats");
  fs::path exr = dir.file("a.exr"), png = dir.file("a.png"), tif = dir.file("a.tif");
  for (const fs::path& out : {exr, png, tif}) radiant_ok("render " + sphere() + " -o " + quoted(out) + sphere_flags + " --transparent");
  TestImage linear = read_image(exr), shown = read_image(png), tiff = read_image(tif);
  REQUIRE(linear.channel_names == std::vector<std::string>{"R", "G", "B", "A"});
  REQUIRE(shown.channel_names == std::vector<std::string>{"R", "G", "B", "A"});
  REQUIRE(tiff.channels == 4);
  int opaque = 0, clear = 0, partial = 0;
  for (int y = 0; y < linear.height; ++y)
    for (int x = 0; x < linear.width; ++x) {
      CAPTURE(x);
      CAPTURE(y);
      float alpha = linear.at(x, y, 3);
      CHECK(std::abs(shown.at(x, y, 3) - alpha) <= 0.5f / 255 + 1e-6f);
      CHECK(std::abs(tiff.at(x, y, 3) - alpha) <= 0.5f / 255 + 1e-6f);
      if (alpha == 0) {
        ++clear;
        for (int c = 0; c < 3; ++c) CHECK(linear.at(x, y, c) == 0);  // no sky, no color
        continue;
      }
      opaque += alpha == 1, partial += alpha < 1;
      for (int c = 0; c < 3; ++c) {
        float straight = std::min(1.0f, linear.at(x, y, c) / alpha);
        CHECK(std::abs(shown.at(x, y, c) - linear_to_srgb(straight)) <= 0.5f / 255 + 1e-5f);
      }
    }
  CHECK(opaque > 0);
  CHECK(clear > 0);
  CHECK(partial > 0);
}

TEST_CASE("transparent cli: without --transparent the sky is seen and there is no alpha, .scene's transparent turns it on") {
  ScratchDir dir("transparent-setting");
  fs::path plain = dir.file("plain.exr"), set = dir.file("set.exr"), flag = dir.file("flag.exr");
  radiant_ok("render " + sphere() + " -o " + quoted(plain) + sphere_flags);
  TestImage image = read_image(plain);
  CHECK(image.channel_names == std::vector<std::string>{"R", "G", "B"});
  CHECK(image.at(0, 0, 0) == doctest::Approx(0.5f));
  std::string text = read_bytes(source_path("assets/first-render.scene")) + "transparent true\n";  // @render is last
  fs::path scene = dir.write("sphere.scene", text);
  radiant_ok("render " + quoted(scene) + " -o " + quoted(set) + sphere_flags);
  radiant_ok("render " + sphere() + " -o " + quoted(flag) + sphere_flags + " --transparent");
  TestImage a = read_image(set), b = read_image(flag);
  REQUIRE(a.channel_names == b.channel_names);
  CHECK(a.pixels == b.pixels);
}

TEST_CASE("transparent cli: a format without alpha is a usage error, writing nothing") {
  ScratchDir dir("transparent-jpeg");
  fs::path jpg = dir.file("a.jpg");
  CommandResult r = run_radiant("render " + sphere() + " -o " + quoted(jpg) + sphere_flags + " --transparent");
  CHECK(r.exit_code == 2);
  CHECK(dir.without_path(r.err) == "radiant render: --transparent needs an output with alpha: PNG, TIFF or EXR (got 'a.jpg')\n");
  CHECK_FALSE(fs::exists(jpg));
}

TEST_CASE("transparent cli: shards of a transparent render merge to its pixels and alpha bit for bit") {
  ScratchDir dir("transparent-merge");
  std::string flags = sphere_flags + " --transparent --mode path --sampler sobol";
  fs::path single_exr = dir.file("single.exr"), single_png = dir.file("single.png");
  radiant_ok("render " + sphere() + " -o " + quoted(single_exr) + flags);
  radiant_ok("render " + sphere() + " -o " + quoted(single_png) + flags);
  std::string shards;
  for (int i = 0; i < 4; ++i) {
    fs::path shard = dir.file("s" + std::to_string(i) + ".exr");
    radiant_ok("render " + sphere() + " -o " + quoted(shard) + flags + " --shard " + std::to_string(i) + "/4 --split both");
    shards = quoted(shard) + " " + shards;
  }
  fs::path merged_exr = dir.file("merged.exr"), merged_png = dir.file("merged.png");
  radiant_ok("merge " + shards + " -o " + quoted(merged_exr) + " --quiet");
  radiant_ok("merge " + shards + " -o " + quoted(merged_png) + " --quiet");
  TestImage x = read_image(single_exr), y = read_image(merged_exr);
  REQUIRE(x.channel_names == std::vector<std::string>{"R", "G", "B", "A"});
  REQUIRE(x.channel_names == y.channel_names);
  REQUIRE(x.pixels.size() == y.pixels.size());
  CHECK(std::memcmp(x.pixels.data(), y.pixels.data(), x.pixels.size() * sizeof(float)) == 0);
  CHECK(same_pixels(single_png, merged_png));
  // They do not merge into a format without alpha.
  CommandResult jpeg = run_radiant("merge " + shards + " -o " + quoted(dir.file("merged.jpg")));
  CHECK(jpeg.exit_code == 1);
  CHECK(dir.without_path(jpeg.err) ==
        "radiant: the shards are of a --transparent render: -o needs an output with alpha: PNG, TIFF or EXR (got 'merged.jpg')\n");
  CHECK_FALSE(fs::exists(dir.file("merged.jpg")));
  // An opaque shard does not merge with transparent ones.
  fs::path opaque = dir.file("opaque.exr");
  radiant_ok("render " + sphere() + " -o " + quoted(opaque) + sphere_flags + " --mode path --sampler sobol --shard 0/4 --split both");
  CommandResult r = run_radiant("merge " + quoted(opaque) + " " + quoted(dir.file("s1.exr")) + " " + quoted(dir.file("s2.exr")) +
                                " " + quoted(dir.file("s3.exr")) + " -o " + quoted(dir.file("refused.exr")));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("(rendered with and without --transparent)") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.file("refused.exr")));
}
