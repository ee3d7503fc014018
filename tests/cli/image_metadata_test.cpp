// The metadata every image carries (docs/cli.md, "Image metadata"): render, batch and merge
// record how they made it, and --no-metadata records nothing (the same bytes every time).
#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

#include "support/test_scenes.h"
#include "support/radiant_ok.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

const char* tiny = " --width 8 --height 8 --spp 2 --seed 7 --mode path --quiet";

}  // namespace

TEST_CASE("image metadata: a render records radiant's version, its command line, scene, settings, time and rays") {
  ScratchDir dir("metadata-render");
  fs::path scene = dir.write("plane.scene", lit_plane_scene);
  for (const char* name : {"out.png", "out.exr"}) {
    CAPTURE(name);
    fs::path out = dir.file(name), stats = dir.file("stats.json");
    std::string args = "render " + scene.string() + " -o " + out.string() + tiny + " --stats " + stats.string();
    radiant_ok(args);
    CHECK(image_attribute(out, "Software") == "radiant " RADIANT_VERSION);
    CHECK(image_attribute(out, "Comment") == "radiant " + args);
    CHECK(image_attribute(out, "radiant:scene") == scene.string());
    CHECK(image_attribute(out, "radiant:mode") == "path");
    CHECK(image_attribute(out, "radiant:sampler") == "sobol");
    CHECK(image_attribute(out, "radiant:spp") == "2");
    CHECK(image_attribute(out, "radiant:seed") == "7");
    nlohmann::json json = nlohmann::json::parse(read_bytes(stats));
    CHECK(image_attribute(out, "radiant:rays") == std::to_string(json["rays"]["total"].get<uint64_t>()));
    CHECK(std::stod(image_attribute(out, "radiant:render_seconds")) == doctest::Approx(json["seconds"]["render"].get<double>()).epsilon(1e-5));
    CHECK(std::stod(image_attribute(out, "radiant:rays_per_second")) > 0);
  }
}

TEST_CASE("image metadata: a batch image records the script and its line, --no-metadata on a line records nothing") {
  ScratchDir dir("metadata-batch");
  dir.write("plane.scene", lit_plane_scene);
  fs::path script = dir.write("views.txt", std::string("scene plane.scene\n  render -o a.png") + tiny +
                                               "   # the first view\nrender -o b.png --no-metadata" + tiny + "\n");
  radiant_ok("batch " + script.string());
  CHECK(image_attribute(dir.file("a.png"), "Comment") ==
        "radiant batch " + script.string() + " # line 2: render -o a.png" + tiny);
  CHECK(image_attribute(dir.file("a.png"), "radiant:scene") == dir.file("plane.scene").string());
  CHECK(image_attribute(dir.file("b.png"), "Software").empty());
  CHECK(same_pixels(dir.file("a.png"), dir.file("b.png")));
}

TEST_CASE("image metadata: merge --no-metadata writes the same bytes twice, shards without a record leave their settings") {
  ScratchDir dir("metadata-merge");
  fs::path scene = dir.write("plane.scene", lit_plane_scene);
  std::string shards;
  for (int i = 0; i < 2; ++i) {
    fs::path shard = dir.file("s" + std::to_string(i) + ".exr");
    radiant_ok("render " + scene.string() + " -o " + shard.string() + tiny + " --no-metadata --shard " + std::to_string(i) + "/2");
    CHECK(image_attribute(shard, "radiant:format") == "radiant shard 1");  // what merge needs stays
    CHECK(image_attribute(shard, "Software").empty());
    shards += " " + shard.string();
  }
  radiant_ok("merge" + shards + " -o " + dir.file("a.png").string() + " --no-metadata");
  radiant_ok("merge" + shards + " -o " + dir.file("b.png").string() + " --no-metadata --quiet");
  CHECK(read_bytes(dir.file("a.png")) == read_bytes(dir.file("b.png")));
  CHECK(image_attribute(dir.file("a.png"), "Software").empty());
  fs::path recorded = dir.file("recorded.png");
  radiant_ok("merge" + shards + " -o " + recorded.string());
  CHECK(image_attribute(recorded, "Software") == "radiant " RADIANT_VERSION);
  CHECK(image_attribute(recorded, "radiant:spp") == "2");
  CHECK(image_attribute(recorded, "radiant:seed") == "7");
  CHECK(image_attribute(recorded, "radiant:shards") == "2");
  CHECK(image_attribute(recorded, "radiant:render_seconds").empty());  // the shards recorded none
}
