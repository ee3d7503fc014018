// `radiant render` as users and scripts drive it: exit codes, errors, outputs, determinism.
#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

const char* lit_plane_scene = R"(scene analytic plane
@camera
position 0 5 0
direction 0 -1 0
up 0 0 -1
orthographic 4
@light point
color 255 255 255
position 0.5 2 0.25
attenuation 1 0.1 0.05
@plane
point 0 0 0
normal 0 1 0
kd 0.6
)";


}  // namespace

TEST_CASE("render cli: a .scene point-lit plane in EXR equals kd*I*cos/(kc+kl*d+kq*d^2) in the format's units") {
  ScratchDir dir("cli-analytic");
  fs::path scene = dir.write("plane.scene", lit_plane_scene);
  fs::path out = dir.file("plane.exr");
  CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(out) +
                                " --width 8 --height 8 --spp 1 --mode whitted --quiet");
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.empty());
  TestImage img = read_image(out);
  REQUIRE(img.width == 8);
  for (auto [x, y] : {std::pair{0, 0}, {3, 5}, {7, 2}}) {
    float px = -2 + 0.5f * (x + 0.5f), pz = -(2 - 0.5f * (y + 0.5f));
    float dx = 0.5f - px, dy = 2, dz = 0.25f - pz;
    float d = std::sqrt(dx * dx + dy * dy + dz * dz);
    // In the format's units a value of 255 is full white: internal = value / 255.
    float expected = 0.6f * 255 * (dy / d) / (1 + 0.1f * d + 0.05f * d * d) / 255;
    CHECK(img.at(x, y, 0) == doctest::Approx(expected).epsilon(1e-4));
  }
}

TEST_CASE("render cli: --threads 1 and --threads 2 give the same pixels and settings, and with --no-metadata the same bytes") {
  ScratchDir dir("cli-threads");
  fs::path showcase = source_path("assets/showcase.scene");
  for (std::string mode : {"whitted", "path"}) {
    std::string extension = mode == "path" ? ".exr" : ".png";  // EXR carries no time stamp either
    fs::path a = dir.file("a-" + mode + extension), b = dir.file("b-" + mode + extension);
    std::string common = " --width 48 --height 36 --spp 4 --quiet --mode " + mode;
    REQUIRE(run_radiant("render " + quoted(showcase) + " -o " + quoted(a) + " --threads 1" + common).exit_code == 0);
    REQUIRE(run_radiant("render " + quoted(showcase) + " -o " + quoted(b) + " --threads 2" + common).exit_code == 0);
    CHECK(same_pixels(a, b));
    for (const char* field : {"Software", "radiant:scene", "radiant:mode", "radiant:sampler", "radiant:spp", "radiant:seed", "radiant:rays"})
      CHECK(image_attribute(a, field) == image_attribute(b, field));
    CHECK(read_bytes(a) != read_bytes(b));  // the command lines (and times) they record differ
    fs::path bare_a = dir.file("bare-a-" + mode + extension), bare_b = dir.file("bare-b-" + mode + extension);
    REQUIRE(run_radiant("render " + quoted(showcase) + " -o " + quoted(bare_a) + " --threads 1 --no-metadata" + common).exit_code == 0);
    REQUIRE(run_radiant("render " + quoted(showcase) + " -o " + quoted(bare_b) + " --threads 2 --no-metadata" + common).exit_code == 0);
    CHECK(read_bytes(bare_a) == read_bytes(bare_b));
    CHECK(same_pixels(bare_a, a));
    CHECK(image_attribute(bare_a, "Software").empty());
  }
}

TEST_CASE("render cli: a scene on standard input renders") {
  ScratchDir dir("cli-stdin");
  fs::path out = dir.file("stdin.png");
  CommandResult r = run_radiant("render - -o " + quoted(out) + " --width 8 --height 8 --quiet", lit_plane_scene);
  CHECK(r.exit_code == 0);
  CHECK(fs::exists(out));
}

TEST_CASE("render cli: a bad scene file exits 1 with one line naming file:line:col and writes nothing") {
  ScratchDir dir("cli-bad-scene");
  fs::path scene = dir.write("bad.scene", "@sphere\nradius -2\ncenter 0 0 0\n");
  fs::path out = dir.file("out.png");
  CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(out));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("bad.scene:2:8:") != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("render cli: an existing output file is left untouched when the render fails") {
  ScratchDir dir("cli-keep");
  fs::path out = dir.write("keep.png", "precious");
  CommandResult r = run_radiant("render " + quoted(dir.file("missing.scene")) + " -o " + quoted(out));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("missing.scene") != std::string::npos);
  CHECK(read_bytes(out) == "precious");
  // No temporary files are left beside it either.
  CHECK(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()) == 1);
}

TEST_CASE("render cli: bad flags exit 2 with a clear message and write nothing") {
  ScratchDir dir("cli-flags");
  fs::path scene = dir.write("ok.scene", lit_plane_scene);
  fs::path out = dir.file("out.png");
  std::string base = "render " + quoted(scene) + " -o " + quoted(out) + " ";
  for (std::string flags : {"--spp 0", "--mode magic", "--sampler sobolx", "--width -3", "--frobnicate",
                            "--env-color 1,2", "--look-from 1,2,x", "--crop 0,0,9999,10", "--effects=-sparkles"}) {
    CAPTURE(flags);
    CommandResult r = run_radiant(base + flags);
    CHECK(r.exit_code == 2);
    CHECK_FALSE(r.err.empty());
    CHECK_FALSE(fs::exists(out));
  }
  CommandResult missing_output = run_radiant("render " + quoted(scene));
  CHECK(missing_output.exit_code == 2);
}

TEST_CASE("render cli: an unwritable output path exits 1 naming the file") {
  ScratchDir dir("cli-unwritable");
  fs::path scene = dir.write("ok.scene", lit_plane_scene);
  CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(dir.file("no/such/dir/out.png")) + " --width 4 --height 4");
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("out.png") != std::string::npos);
}

TEST_CASE("render cli: --help shows examples and --version the version, both exit 0") {
  CommandResult help = run_radiant("render --help");
  CHECK(help.exit_code == 0);
  CHECK(help.out.find("Examples:") != std::string::npos);
  CommandResult version = run_radiant("--version");
  CHECK(version.exit_code == 0);
  CHECK(version.out.rfind("radiant ", 0) == 0);
}

TEST_CASE("render cli: the summary line reports resolution, spp, time and rays/s unless --quiet") {
  ScratchDir dir("cli-summary");
  fs::path scene = dir.write("ok.scene", lit_plane_scene);
  CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(dir.file("o.png")) + " --width 10 --height 6 --spp 2");
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find("10x6") != std::string::npos);
  CHECK(r.err.find("2 spp") != std::string::npos);
  CHECK(r.err.find("rays/s") != std::string::npos);
}

TEST_CASE("render cli: adaptive sampling reports the distribution of per-pixel samples and the estimated error") {
  ScratchDir dir("cli-adaptive");
  fs::path stats = dir.file("stats.json");
  CommandResult r = run_radiant("render " + quoted(source_path("assets/showcase.scene")) + " -o " + quoted(dir.file("a.png")) +
                                " --width 32 --height 32 --spp 128 --noise-threshold 0.05 --stats " + quoted(stats));
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find("spp per pixel (median") != std::string::npos);
  nlohmann::json json = nlohmann::json::parse(read_bytes(stats));
  CHECK(json["pixel_samples"]["min"] == 64);  // Cycles' minimum for 0.05 (40), as a power of two
  CHECK(json["pixel_samples"]["max"] == 128);
  CHECK(json["pixel_samples"]["median"] >= 8);
  CHECK(json["estimated_relative_error"] > 0);
}

TEST_CASE("render cli: --camera picks a camera by index or name, an unknown one is a usage error listing the cameras") {
  ScratchDir dir("cli-camera");
  fs::path scene = dir.write("two.scene",
                             "@camera front\nposition 0 0 5\ndirection 0 0 -1\n"
                             "@camera top\nposition 0 5 0\ndirection 0 -1 0\nup 0 0 -1\n"
                             "@sphere\nradius 1\ncenter 0 0 0\nemission 255 255 255\n");
  std::string base = "render " + quoted(scene) + " --width 8 --height 8 --spp 1 --mode whitted --quiet -o ";
  REQUIRE(run_radiant(base + quoted(dir.file("by-index.png")) + " --camera 1").exit_code == 0);
  REQUIRE(run_radiant(base + quoted(dir.file("by-name.png")) + " --camera top").exit_code == 0);
  CHECK(same_pixels(dir.file("by-index.png"), dir.file("by-name.png")));
  CommandResult r = run_radiant(base + quoted(dir.file("none.png")) + " --camera side");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("no camera 'side'") != std::string::npos);
  CHECK(r.err.find("1 'top'") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.file("none.png")));
}

TEST_CASE("render cli: --quiet prints nothing, not even TBB's warning for more threads than cores") {
  ScratchDir dir("cli-many-threads");
  fs::path scene = dir.write("plane.scene", lit_plane_scene);
  fs::path one = dir.file("one.exr"), many = dir.file("many.exr");
  CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(many) +
                                " --width 8 --height 8 --spp 2 --mode path --quiet --threads 1024");
  CHECK(r.exit_code == 0);
  CHECK(r.err == "");
  REQUIRE(run_radiant("render " + quoted(scene) + " -o " + quoted(one) +
                      " --width 8 --height 8 --spp 2 --mode path --quiet --threads 1")
              .exit_code == 0);
  CHECK(same_pixels(one, many));
}

TEST_CASE("render cli: a side derived from an extreme camera aspect is out of range, not an int overflow") {
  // Width 8 over an aspect of 1e-30 asks for a height of 8e30: lround's result did not fit in an
  // int, and the image came out 8x1.
  ScratchDir dir("cli-extreme-aspect");
  fs::path scene = dir.write("tall.scene", "@camera\nposition 0 0 5\ndirection 0 0 -1\nup 0 1 0\nview-distance 1\n"
                                           "view-size 1e-30 1\n@sphere\ncenter 0 0 0\nradius 1\n@light point\n"
                                           "position 0 3 3\n");
  fs::path out = dir.file("tall.png");
  CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(out) + " --width 8 --spp 1 --quiet");
  CHECK(r.exit_code == 2);
  CHECK(r.err == "radiant render: image size 8x8e+30 is out of range (1 to 65536)\n");
  CHECK_FALSE(fs::exists(out));
}

namespace {

// The mean of every channel of every pixel.
double mean_value(const TestImage& image) {
  double sum = 0;
  for (float v : image.pixels) sum += v;
  return image.pixels.empty() ? 0 : sum / double(image.pixels.size());
}

}  // namespace

TEST_CASE("render cli: a scene nothing lights gets the studio environment, said before rendering, unless the flags light it") {
  ScratchDir dir("cli-dark");
  fs::path obj = dir.write("dark.obj", "v -1 -1 -3\nv 1 -1 -3\nv 0 1 -3\nf 1 2 3\n");
  std::string render = "render " + quoted(obj) + " --width 8 --height 8 --spp 4";
  CommandResult studio = run_radiant(render + " -o " + quoted(dir.file("studio.exr")));
  REQUIRE(studio.exit_code == 0);
  size_t note = studio.err.find(obj.string() + ": nothing in the file lights it; using the built-in studio environment");
  CHECK(note != std::string::npos);
  CHECK(note < studio.err.find("wrote "));  // said before the render, not after it
  CHECK(mean_value(read_image(dir.file("studio.exr"))) > 0.1);
  for (const char* flags : {" --env none", " --env-color 1,1,1", " --env studio"}) {
    CAPTURE(flags);
    CommandResult chosen = run_radiant(render + flags + " -o " + quoted(dir.file("chosen.exr")));
    REQUIRE(chosen.exit_code == 0);
    CHECK(chosen.err.find("nothing in the file lights it") == std::string::npos);
  }
  CHECK(mean_value(read_image(dir.file("chosen.exr"))) > 0.1);  // --env studio, asked for
  REQUIRE(run_radiant(render + " --env none --quiet -o " + quoted(dir.file("black.exr"))).exit_code == 0);
  CHECK(mean_value(read_image(dir.file("black.exr"))) == 0);
}

TEST_CASE("render cli: auto mode's reason is printed before rendering and is right for an emissive-only scene") {
  ScratchDir dir("cli-auto-emissive");
  fs::path scene = dir.write("glow.scene", "@camera\nposition 0 0 5\ndirection 0 0 -1\nup 0 1 0\n"
                                           "@sphere\ncenter 0 0 0\nradius 1\nemission 255 128 0\n");
  std::string render = "render " + quoted(scene) + " -o " + quoted(dir.file("o.png")) + " --width 8 --height 8 --spp 1";
  CommandResult dark = run_radiant(render + " --env none");
  REQUIRE(dark.exit_code == 0);
  size_t reason = dark.err.find("mode whitted: one convex emissive object and no other light");
  CHECK(reason != std::string::npos);
  CHECK(reason < dark.err.find("wrote "));
  // Emission no brighter than a glTF emissive factor lights nothing: the plain render is lit by
  // the studio, which only the path tracer samples.
  CommandResult plain = run_radiant(render);
  REQUIRE(plain.exit_code == 0);
  CHECK(plain.err.find("mode path: the background lights the scene") != std::string::npos);
  CHECK(plain.err.find("nothing in the file lights it") != std::string::npos);
}

TEST_CASE("render cli: one side from the flags keeps the shape of the scene's image, as Cycles' percentage does") {
  ScratchDir dir("cli-one-side");
  fs::path scene = dir.write("wide.scene", "@render\nwidth 800\nheight 450\n@camera\nposition 0 0 5\ndirection 0 0 -1\n"
                                           "up 0 1 0\n@sphere\ncenter 0 0 0\nradius 1\nkd 0.5\n@light point\nposition 0 4 4\n");
  struct Case {
    const char* flags;
    int width, height;
  };
  for (Case c : {Case{"--width 400", 400, 225}, Case{"--height 90", 160, 90}, Case{"--width 100 --height 100", 100, 100}}) {
    CAPTURE(c.flags);
    REQUIRE(run_radiant("render " + quoted(scene) + " -o " + quoted(dir.file("o.png")) + " --spp 1 -q " + c.flags).exit_code == 0);
    TestImage image = read_image(dir.file("o.png"));
    CHECK(image.width == c.width);
    CHECK(image.height == c.height);
  }
}

TEST_CASE("render cli: a mode that leaves out light the scene has says so, auto and a mode that keeps it do not") {
  ScratchDir dir("cli-dropped-light");
  auto notes = [&](const std::string& scene, const std::string& flags) {
    CommandResult r = run_radiant("render " + quoted(source_path(scene)) + " -o " + quoted(dir.file("o.png")) +
                                  " --width 8 --height 8 --spp 1 " + flags);
    REQUIRE(r.exit_code == 0);
    return r.err;
  };
  CHECK(notes("assets/cornell.gltf", "--mode whitted").find("warning: mode whitted: emissive surfaces are only seen") !=
        std::string::npos);
  CHECK(notes("assets/showcase.scene", "--mode path").find("warning: mode path: the ambient light is ignored") !=
        std::string::npos);
  CHECK(notes("assets/cornell.gltf", "--mode path").find("warning") == std::string::npos);
  CHECK(notes("assets/cornell.gltf", "").find("warning") == std::string::npos);
  CHECK(notes("assets/showcase.scene", "").find("warning") == std::string::npos);
}
