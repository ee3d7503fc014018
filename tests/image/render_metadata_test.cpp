// What an image records about the render that made it (image/render_metadata.h): every field
// comes back from each format radiant writes, PNG text takes tEXt or iTXt as PNG asks, formats
// that keep only their own fields carry it packed, and a foreign image holds no record.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>

#include "image/image_io.h"
#include "image/image_writer.h"
#include "image/packed_metadata.h"
#include "image/render_metadata.h"
#include "output/output_set.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// Every field set, with text each container must keep: spaces, quotes, a newline, a backslash
// and Greek in UTF-8.
RenderRecord every_field() {
  return {"0.1.0",
          "radiant render 'my scene.gltf' -o out.png --env-color 1,1,1 # it's \"quoted\"\nand \\ more",
          "σκηνή/scene.gltf",
          "path",
          "sobol",
          64,
          7,
          1.25,
          123456789012};
}

// A 2x2 gray image with `metadata`, written as radiant writes renders.
void write_gray(const std::string& path, const ImageMetadata& metadata, int bit_depth = 8) {
  OutputImage image;
  image.width = 2, image.height = 2;
  image.channels = {"R", "G", "B"};
  image.pixels.assign(12, 0.5f);
  image.metadata = metadata;
  image.bit_depth = bit_depth;
  OutputSet outputs;
  write_image(outputs.create(path), image);
  outputs.commit();
}

}  // namespace

TEST_CASE("render metadata: every field comes back from PNG, EXR, TIFF and 16-bit PNG, with rays per second") {
  ScratchDir dir("render-metadata");
  RenderRecord record = every_field();
  for (const char* name : {"r.png", "r.exr", "r.tif", "deep.png"}) {
    CAPTURE(name);
    std::string path = dir.file(name).string();
    write_gray(path, render_metadata(record), std::string(name) == "deep.png" ? 16 : 8);
    ImageMetadata read = read_image_header(path, nullptr).metadata;
    CHECK(parse_render_metadata(read) == record);
    CHECK(find_attribute(read, "Software") == "radiant 0.1.0");
    CHECK(find_attribute(read, "radiant:rays_per_second") == "98765431210");  // 123456789012 / 1.25 s
  }
}

TEST_CASE("render metadata: PNG keeps ASCII in tEXt, UTF-8 beyond it in iTXt, and other bytes as tEXt's Latin-1, in order") {
  ScratchDir dir("render-metadata-png");
  std::string path = dir.file("text.png").string();
  ImageMetadata written = {{"Comment", "plain words"}, {"radiant:scene", "σκηνή.scene"}, {"radiant:other", "caf\xe9"}};
  write_gray(path, written);
  std::string bytes = read_bytes(path);
  CHECK(bytes.find(std::string("tEXtComment\0plain words", 23)) != std::string::npos);
  CHECK(bytes.find(std::string("iTXtradiant:scene\0\0\0\0\0σκηνή.scene", 17 + 5 + std::string("σκηνή.scene").size())) !=
        std::string::npos);
  CHECK(bytes.find(std::string("tEXtradiant:other\0caf\xe9", 22)) != std::string::npos);
  CHECK(read_image_header(path, nullptr).metadata == written);
}

TEST_CASE("render metadata: an image radiant did not record has no record, a damaged record names the attribute") {
  CHECK_FALSE(parse_render_metadata({}).has_value());
  ImageMetadata foreign = {{"Software", "GIMP 2.10"}, {"Comment", "holiday"}, {"Title", "beach"}};
  CHECK_FALSE(parse_render_metadata(foreign).has_value());
  CHECK(radiant_attributes(foreign).empty());
  ImageMetadata damaged = render_metadata(every_field());
  std::erase_if(damaged, [](const auto& attribute) { return attribute.first == "radiant:mode"; });
  CHECK_THROWS_WITH_AS(parse_render_metadata(damaged), "no radiant:mode attribute", std::runtime_error);
  damaged = render_metadata(every_field());
  for (auto& [name, value] : damaged)
    if (name == "radiant:spp") value = "many";
  CHECK_THROWS_WITH_AS(parse_render_metadata(damaged), "radiant:spp 'many' is not a number", std::runtime_error);
}

TEST_CASE("render metadata: radiant's attributes are Software and Comment when Software names radiant, and radiant:*") {
  ImageMetadata mixed = {{"Software", "radiant 0.1.0"}, {"Comment", "radiant render a.scene -o a.png"},
                         {"Title", "kept out"},       {"radiant:spp", "4"}};
  CHECK(radiant_attributes(mixed) == ImageMetadata{{"Software", "radiant 0.1.0"},
                                                   {"Comment", "radiant render a.scene -o a.png"},
                                                   {"radiant:spp", "4"}});
}

TEST_CASE("render metadata: a packed description gives back every attribute, a foreign description stays as it is") {
  ImageMetadata metadata = render_metadata(every_field());
  ImageMetadata packed = packed_metadata(metadata);
  REQUIRE(packed.size() == 2);  // Software for viewers, and the description
  CHECK(packed[0] == std::pair<std::string, std::string>("Software", "radiant 0.1.0"));
  CHECK(packed[1].first == "ImageDescription");
  CHECK(unpacked_metadata(packed) == metadata);
  ImageMetadata foreign = {{"ImageDescription", "a: b\nc: d"}};
  CHECK(unpacked_metadata(foreign) == foreign);
  CHECK(packed_metadata({}).empty());
}

TEST_CASE("render metadata: records of the shards of one image combine into one with times and rays summed") {
  RenderRecord a = every_field(), b = every_field();
  b.render_seconds = 0.5, b.rays = 1000, b.command_line = "radiant render other";
  RenderRecord combined = combined_record({a, b});
  CHECK(combined.render_seconds == 1.75);
  CHECK(combined.rays == 123456790012);
  CHECK(combined.command_line == a.command_line);
  CHECK(combined.spp == 64);
}
