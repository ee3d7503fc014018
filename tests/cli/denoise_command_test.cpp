// --denoise on render and batch, --aov noisy and halves (in shards too), and `radiant denoise IN.exr -o OUT`
// (docs/denoise.md): the same denoised colour either way, recorded as denoised, alpha kept, and
// an EXR without the needed channels refused in one line.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "support/radiant_ok.h"
#include "support/test_scenes.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

const char* small = " --width 24 --height 24 --spp 8 --seed 3 --mode path --env-color 0.5,0.5,0.5 --quiet";

// How many values of channels [0, 3) differ between two images of the same size.
int color_differences(const TestImage& a, const TestImage& b) {
  int different = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c) different += a.at(x, y, c) != b.at(x, y, c);
  return different;
}

int channel(const TestImage& image, const std::string& name) {
  for (int c = 0; c < image.channels; ++c)
    if (image.channel_names[size_t(c)] == name) return c;
  return -1;
}

}  // namespace

TEST_CASE("denoise cli: render --denoise changes the colour, --aov noisy keeps the raw render's, the image says denoised") {
  ScratchDir dir("denoise-render");
  fs::path scene = dir.write("sphere.scene", lit_sphere_scene);
  fs::path raw = dir.file("raw.exr"), denoised = dir.file("denoised.exr"), png = dir.file("denoised.png");
  radiant_ok("render " + scene.string() + " -o " + raw.string() + small);
  radiant_ok("render " + scene.string() + " -o " + denoised.string() + small + " --denoise --aov noisy");
  radiant_ok("render " + scene.string() + " -o " + png.string() + small + " --denoise");
  TestImage a = read_image(raw), b = read_image(denoised);
  REQUIRE(channel(b, "noisy.R") == 3);
  int unchanged = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c) {
        CHECK(b.at(x, y, 3 + c) == a.at(x, y, c));  // the raw colour, to the bit
        unchanged += b.at(x, y, c) == a.at(x, y, c);
      }
  CHECK(unchanged < a.width * a.height);
  CHECK(image_attribute(denoised, "radiant:denoised") == "yes");
  CHECK(image_attribute(png, "radiant:denoised") == "yes");
  CHECK(image_attribute(raw, "radiant:denoised").empty());
}

TEST_CASE("denoise cli: radiant denoise of an EXR with the halves gives render --denoise's colour") {
  ScratchDir dir("denoise-command");
  fs::path scene = dir.write("sphere.scene", lit_sphere_scene);
  fs::path channels = dir.file("channels.exr"), rendered = dir.file("rendered.exr"), command = dir.file("command.exr");
  radiant_ok("render " + scene.string() + " -o " + channels.string() + small +
             " --aov albedo,normal,depth,variance,halves");
  radiant_ok("render " + scene.string() + " -o " + rendered.string() + small + " --denoise --threads 1");
  radiant_ok("denoise " + channels.string() + " -o " + command.string() + " --threads 2 --quiet");
  TestImage from_render = read_image(rendered), from_command = read_image(command);
  CHECK(color_differences(from_render, from_command) == 0);
  CHECK(image_attribute(command, "radiant:denoised") == "yes");
  CHECK(channel(from_command, "even.R") >= 0);  // an EXR keeps every input channel
}

TEST_CASE("denoise cli: shards with --aov halves merge to the one render's channels, and the merge denoises like it") {
  ScratchDir dir("denoise-shards");
  fs::path scene = dir.write("sphere.scene", lit_sphere_scene);
  const std::string aovs = " --aov albedo,normal,depth,variance,halves";
  fs::path single = dir.file("single.exr"), merged = dir.file("merged.exr"), denoised = dir.file("denoised.exr");
  fs::path rendered = dir.file("rendered.exr");
  std::string shards;
  for (int i = 0; i < 3; ++i) {
    fs::path shard = dir.file("shard-" + std::to_string(i) + ".exr");
    radiant_ok("render " + scene.string() + " -o " + shard.string() + small + aovs + " --shard " + std::to_string(i) +
               "/3 --split both");
    shards += " " + shard.string();
  }
  radiant_ok("merge" + shards + " -o " + merged.string() + " --quiet");
  radiant_ok("render " + scene.string() + " -o " + single.string() + small + aovs);
  TestImage from_shards = read_image(merged), from_render = read_image(single);
  REQUIRE(from_shards.channel_names == from_render.channel_names);
  REQUIRE(channel(from_shards, "odd.R") >= 0);
  int different = 0;
  for (size_t i = 0; i < from_render.pixels.size(); ++i) different += from_shards.pixels[i] != from_render.pixels[i];
  CHECK(different == 0);
  radiant_ok("denoise " + merged.string() + " -o " + denoised.string() + " --quiet");
  radiant_ok("render " + scene.string() + " -o " + rendered.string() + small + " --denoise");
  CHECK(color_differences(read_image(denoised), read_image(rendered)) == 0);
}

TEST_CASE("denoise cli: an EXR without the denoiser's channels is refused in one line, and nothing is written") {
  ScratchDir dir("denoise-missing");
  fs::path scene = dir.write("sphere.scene", lit_sphere_scene);
  fs::path input = dir.file("in.exr"), output = dir.file("out.png");
  radiant_ok("render " + scene.string() + " -o " + input.string() + small + " --aov albedo,normal,depth");
  CommandResult r = run_radiant("denoise " + input.string() + " -o " + output.string());
  CHECK(r.exit_code == 1);
  CHECK(dir.without_path(r.err) ==
        "radiant: in.exr: no channel 'even.R' (the denoiser needs colour, albedo, normal, depth and the half images: "
        "render to EXR with --aov albedo,normal,depth,halves)\n");
  CHECK_FALSE(fs::exists(output));
}

TEST_CASE("denoise cli: --transparent keeps its alpha, --aov noisy needs --denoise, shards refuse --denoise") {
  ScratchDir dir("denoise-alpha");
  fs::path scene = dir.write("sphere.scene", lit_sphere_scene);
  fs::path raw = dir.file("raw.exr"), denoised = dir.file("denoised.exr");
  radiant_ok("render " + scene.string() + " -o " + raw.string() + small + " --transparent");
  radiant_ok("render " + scene.string() + " -o " + denoised.string() + small + " --transparent --denoise");
  TestImage a = read_image(raw), b = read_image(denoised);
  REQUIRE(channel(b, "A") == 3);
  int alpha_differences = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) alpha_differences += a.at(x, y, 3) != b.at(x, y, 3);
  CHECK(alpha_differences == 0);
  CommandResult noisy = run_radiant("render " + scene.string() + " -o " + dir.file("n.exr").string() + small + " --aov noisy");
  CHECK(noisy.exit_code == 2);
  CHECK(noisy.err.find("--aov: noisy is the image before denoising: it needs --denoise") != std::string::npos);
  CommandResult shard = run_radiant("render " + scene.string() + " -o " + dir.file("s.exr").string() + small +
                                    " --denoise --shard 0/2");
  CHECK(shard.exit_code == 2);
  CHECK(shard.err.find("--denoise: is a step after merge") != std::string::npos);
}

TEST_CASE("denoise cli: a batch line takes --denoise") {
  ScratchDir dir("denoise-batch");
  fs::path scene = dir.write("sphere.scene", lit_sphere_scene);
  fs::path script = dir.write("views.txt", "scene sphere.scene\nrender -o a.png" + std::string(small) + " --denoise\n");
  radiant_ok("batch " + script.string());
  CHECK(image_attribute(dir.file("a.png"), "radiant:denoised") == "yes");
}
