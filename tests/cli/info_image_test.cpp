// `radiant info IMAGE`: an image's size, channels, pixel type and the metadata radiant recorded
// in it, as text and JSON; a foreign image says it has none, an unreadable one is an error.
#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

#include "image/image_io.h"
#include "output/output_set.h"
#include "support/test_scenes.h"
#include "support/radiant_ok.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

const char* tiny = " --width 8 --height 8 --spp 2 --seed 7 --mode path --quiet";

}  // namespace

TEST_CASE("info IMAGE: size, channels, pixel type and radiant's metadata, as text and JSON") {
  ScratchDir dir("info-image");
  fs::path scene = dir.write("plane.scene", lit_plane_scene), out = dir.file("out.png");
  radiant_ok("render " + scene.string() + " -o " + out.string() + tiny);
  CommandResult text = radiant_ok("info " + out.string());
  CHECK(text.out.find(out.string() + "\n  size:     8x8\n  channels: 3 (R, G, B)\n  pixels:   uint8, sRGB\n  metadata:\n") == 0);
  CHECK(text.out.find("\n    Software: radiant " RADIANT_VERSION "\n") != std::string::npos);
  CHECK(text.out.find("\n    radiant:seed: 7\n") != std::string::npos);
  nlohmann::json json = nlohmann::json::parse(radiant_ok("info " + out.string() + " --json").out);
  CHECK(json["image"] == out.string());
  CHECK(json["width"] == 8);
  CHECK(json["channels"][2]["name"] == "B");
  CHECK(json["channels"][2]["type"] == "uint8");
  CHECK(json["pixel_type"] == "uint8");
  CHECK(json["metadata"]["radiant:spp"] == "2");
  CHECK(json["metadata"]["Comment"].get<std::string>().rfind("radiant render ", 0) == 0);

  // A shard: a window of a larger image, float color beside exact uint32 sums.
  fs::path shard = dir.file("shard.exr");
  radiant_ok("render " + scene.string() + " -o " + shard.string() + tiny + " --shard 1/2");
  CommandResult shard_info = radiant_ok("info " + shard.string());
  CHECK(shard_info.out.find(" of 8x8\n  channels: ") != std::string::npos);  // "size: WxH at (X, Y) of 8x8"
  CHECK(shard_info.out.find("  pixels:   mixed") != std::string::npos);
  CHECK(shard_info.out.find("    radiant:shard: 1/2\n") != std::string::npos);
}

TEST_CASE("info IMAGE: an image radiant did not record says so, an unreadable one is an error naming it") {
  ScratchDir dir("info-foreign");
  fs::path foreign = dir.file("photo.png");
  ImageWriteSpec spec;
  spec.width = 2, spec.height = 1;
  spec.channel_names = {"R", "G", "B"};
  spec.metadata = {{"Software", "GIMP 2.10"}, {"Comment", "holiday"}};
  std::vector<float> pixels(6, 0.25f);
  OutputSet outputs;
  write_image_file(outputs.create(foreign.string()), spec, pixels.data());
  outputs.commit();
  CommandResult text = radiant_ok("info " + foreign.string());
  CHECK(text.out.find("  no radiant metadata (not written by radiant, or written with --no-metadata)\n") != std::string::npos);
  CHECK(text.out.find("holiday") == std::string::npos);
  CHECK(nlohmann::json::parse(radiant_ok("info " + foreign.string() + " --json").out)["metadata"].is_null());

  fs::path broken = dir.write("broken.png", "\x89PNG\r\n\x1a\n but nothing else");
  CommandResult bad = run_radiant("info " + broken.string());
  CHECK(bad.exit_code == 1);
  CHECK(bad.err.rfind("radiant: " + broken.string() + ": ", 0) == 0);
  CHECK(bad.out.empty());
  CommandResult missing = run_radiant("info " + dir.file("missing.exr").string());
  CHECK(missing.exit_code == 1);
  CHECK(missing.err.find(dir.file("missing.exr").string()) != std::string::npos);
  CHECK(run_radiant("info " + foreign.string() + " --scene 1").exit_code == 2);
}
