// `render --filter`: shards, tiles and threads of a filtered render stay exact, the `.scene`
// setting matches the flag, and bad filters are usage errors.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>
#include <filesystem>
#include <string>

#include "support/radiant_ok.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

void render_ok(const std::string& args) { radiant_ok(args + " --quiet"); }

}  // namespace

TEST_CASE("filter cli: Mitchell and Gaussian renders merge from shards of tiles and samples bit for bit, at any thread count") {
  ScratchDir dir("filter-merge");
  std::string scene = quoted(source_path("assets/cornell.gltf"));
  for (const char* filter : {"mitchell", "gaussian --filter-width 2.5"}) {
    CAPTURE(filter);
    std::string flags = std::string(" --mode path --width 12 --height 10 --spp 8 --max-depth 3 --aov variance --filter ") + filter;
    fs::path single = dir.file("single.exr"), one_thread = dir.file("one-thread.exr"), box = dir.file("box.exr");
    render_ok("render " + scene + " -o " + quoted(single) + flags);
    render_ok("render " + scene + " -o " + quoted(one_thread) + flags + " --threads 1");
    CHECK(same_pixels(single, one_thread));
    std::string shards;
    for (int i = 0; i < 4; ++i) {
      fs::path shard = dir.file("s" + std::to_string(i) + ".exr");
      render_ok("render " + scene + " -o " + quoted(shard) + flags + " --shard " + std::to_string(i) + "/4 --split both");
      shards = quoted(shard) + " " + shards;
    }
    fs::path merged = dir.file("merged.exr");
    render_ok("merge " + shards + " -o " + quoted(merged));
    CHECK(same_pixels(single, merged));
    // And the filter changed the image.
    render_ok("render " + scene + " -o " + quoted(box) + " --mode path --width 12 --height 10 --spp 8 --max-depth 3 --aov variance");
    CHECK(read_image(box).pixels != read_image(single).pixels);
  }
}

TEST_CASE("filter cli: the .scene filter and filter-width settings render as the flags do, and --stats names them") {
  ScratchDir dir("filter-scene");
  std::string text = read_bytes(source_path("assets/first-render.scene")) + "filter blackman-harris\nfilter-width 3\n";
  fs::path scene = dir.write("sphere.scene", text), by_scene = dir.file("scene.exr"), by_flags = dir.file("flags.exr");
  std::string size = " --width 16 --height 16 --spp 4";
  fs::path stats = dir.file("stats.json");
  render_ok("render " + quoted(scene) + " -o " + quoted(by_scene) + size + " --stats " + quoted(stats));
  nlohmann::json json = nlohmann::json::parse(read_bytes(stats));
  CHECK(json["filter"]["name"] == "blackman-harris");
  CHECK(json["filter"]["width"] == 3.0);
  CHECK(json["transparent"] == false);
  render_ok("render " + quoted(source_path("assets/first-render.scene")) + " -o " + quoted(by_flags) + size +
            " --filter blackman-harris --filter-width 3");
  CHECK(same_pixels(by_scene, by_flags));
}

TEST_CASE("filter cli: an unknown filter or a width not above 0 or above 64 is a usage error, writing nothing") {
  ScratchDir dir("filter-bad");
  fs::path out = dir.file("out.png");
  std::string base = "render " + quoted(source_path("assets/first-render.scene")) + " -o " + quoted(out) + " --width 8 --height 8";
  CommandResult name = run_radiant(base + " --filter lanczos");
  CHECK(name.exit_code == 2);
  CHECK(name.err == "radiant render: --filter: unknown filter 'lanczos' (box, triangle, gaussian, mitchell or blackman-harris)\n");
  for (const char* width : {"0", "65", "nan"}) {
    CAPTURE(width);
    CommandResult r = run_radiant(base + " --filter gaussian --filter-width " + width);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--filter-width") != std::string::npos);
  }
  CHECK_FALSE(fs::exists(out));
  fs::path scene = dir.write("wide.scene", read_bytes(source_path("assets/first-render.scene")) + "filter-width 100\n");
  CommandResult wide = run_radiant("render " + quoted(scene) + " -o " + quoted(out));
  CHECK(wide.exit_code == 1);
  CHECK(dir.without_path(wide.err).find("wide.scene:") != std::string::npos);
  CHECK(wide.err.find("wider than 64 pixels") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
}
