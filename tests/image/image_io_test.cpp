// Image files: PNG and EXR written without OpenImageIO, everything else through the module,
// which a render loads only when its output needs it.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "image/image_io.h"
#include "output/output_set.h"
#include "support/test_scenes.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

// The shared libraries the dynamic linker loaded while radiant rendered `scene` to `output`
// (glibc's LD_DEBUG=files log, one file per process).
std::string libraries_loaded_rendering(const ScratchDir& dir, const fs::path& scene, const fs::path& output) {
  fs::path log = dir.file("ld-debug");
  setenv("LD_DEBUG", "files", 1);
  setenv("LD_DEBUG_OUTPUT", log.c_str(), 1);
  CommandResult r = run_radiant("render '" + scene.string() + "' -o '" + output.string() + "' --width 4 --height 4 --quiet");
  unsetenv("LD_DEBUG");
  unsetenv("LD_DEBUG_OUTPUT");
  REQUIRE(r.exit_code == 0);
  std::string loaded;
  for (const auto& entry : fs::directory_iterator(dir.path))
    if (entry.path().filename().string().rfind("ld-debug", 0) == 0) loaded += read_bytes(entry.path());
  return loaded;
}

}  // namespace

TEST_CASE("image files: a render to PNG or EXR never loads OpenImageIO, a render to TIFF loads it through the module") {
  ScratchDir png_dir("io-png"), exr_dir("io-exr"), tiff_dir("io-tiff");
  std::string png_run = libraries_loaded_rendering(png_dir, png_dir.write("plane.scene", lit_plane_scene),
                                                   png_dir.file("out.png"));
  std::string exr_run = libraries_loaded_rendering(exr_dir, exr_dir.write("plane.scene", lit_plane_scene),
                                                   exr_dir.file("out.exr"));
  std::string tiff_run = libraries_loaded_rendering(tiff_dir, tiff_dir.write("plane.scene", lit_plane_scene),
                                                    tiff_dir.file("out.tif"));
  CHECK(png_run.find("libembree3") != std::string::npos);  // the log does list what was loaded
  for (const std::string& run : {png_run, exr_run}) {
    CHECK(run.find("libOpenImageIO") == std::string::npos);
    CHECK(run.find("libradiant_oiio") == std::string::npos);
  }
  CHECK(tiff_run.find("libradiant_oiio") != std::string::npos);
  CHECK(tiff_run.find("libOpenImageIO") != std::string::npos);
  CHECK(fs::exists(png_dir.file("out.png")));
  CHECK(fs::exists(exr_dir.file("out.exr")));
  CHECK(fs::exists(tiff_dir.file("out.tif")));
}

TEST_CASE("image files: a PNG written directly reads back as sRGB, each value rounded to 8 bits") {
  ScratchDir dir("io-roundtrip");
  // 2x1 RGB: rounding at the half-step, clamping of out-of-range values and NaN.
  std::vector<float> values = {0.5f, 1.0f / 255 * 0.49f, 1.0f / 255 * 0.51f, -0.25f, 1.75f, std::nanf("")};
  fs::path file = dir.file("rgb.png");
  write_test_image(file, 2, 1, {"R", "G", "B"}, values);
  std::string error;
  auto input = open_image_file(file.string(), error, nullptr);
  REQUIRE(input);
  const ImageHeader& header = input->header();
  CHECK(header.width == 2);
  CHECK(header.height == 1);
  CHECK(header.channels == 3);
  CHECK(header.color_space == "sRGB");
  std::vector<unsigned char> bytes(6);
  REQUIRE(input->read(3, PixelType::uint8, bytes.data()));
  CHECK(bytes == std::vector<unsigned char>{128, 0, 1, 0, 255, 0});
}

TEST_CASE("image files: an unknown extension is an error naming the reason, and nothing is written") {
  ScratchDir dir("io-unknown");
  ImageWriteSpec spec;
  spec.width = spec.height = 1;
  spec.channel_names = {"R", "G", "B"};
  float pixel[3] = {0.5f, 0.5f, 0.5f};
  {
    OutputSet outputs;
    CHECK_THROWS_WITH(write_image_file(outputs.create(dir.file("out.unknownformat").string()), spec, pixel),
                      doctest::Contains("out.unknownformat"));
  }
  CHECK(fs::is_empty(dir.path));  // neither the file nor its temporary
}

TEST_CASE("image files: radiant's PNG reader agrees with OpenImageIO's, alpha read as stored") {
  ScratchDir dir("io-png-reader");
  struct Case {
    const char* name;
    std::vector<std::string> channels;
    std::vector<float> values;  // 2x1 pixels
  };
  for (const Case& c : {Case{"gray.png", {"Y"}, {0.25f, 0.75f}},
                        Case{"rgb.png", {"R", "G", "B"}, {0.1f, 0.2f, 0.3f, 0.9f, 0.8f, 0.7f}},
                        Case{"rgba.png", {"R", "G", "B", "A"}, {0.1f, 0.2f, 0.3f, 1, 0.9f, 0.8f, 0.7f, 1}}}) {
    CAPTURE(c.name);
    fs::path file = dir.file(c.name);
    write_test_image(file, 2, 1, c.channels, c.values);
    std::string error;
    auto ours = open_image_file(file.string(), error, nullptr);
    auto theirs = image_io_module().open(file.string(), error);
    REQUIRE(ours);
    REQUIRE(theirs);
    CHECK(ours->header().channel_names == theirs->header().channel_names);
    CHECK(ours->header().alpha_channel == theirs->header().alpha_channel);
    CHECK(ours->header().color_space == theirs->header().color_space);
    int channels = ours->header().channels;
    std::vector<float> a(2 * size_t(channels)), b(a.size());
    REQUIRE(ours->read(channels, PixelType::float32, a.data()));
    REQUIRE(theirs->read(channels, PixelType::float32, b.data()));
    CHECK(a == b);
  }
  // Partly transparent: OpenImageIO premultiplies on reading; the file's own values are unassociated.
  fs::path file = dir.file("half.png");
  // A display image's alpha is written straight, as given: the file stores 0.2 (51) and alpha 102.
  write_test_image(file, 1, 1, {"R", "G", "B", "A"}, {0.2f, 0.2f, 0.2f, 0.4f});
  std::string error;
  auto input = open_image_file(file.string(), error, nullptr);
  REQUIRE(input);
  std::vector<unsigned char> bytes(4);
  REQUIRE(input->read(4, PixelType::uint8, bytes.data()));
  CHECK(bytes == std::vector<unsigned char>{51, 51, 51, 102});
}

TEST_CASE("image files: a truncated PNG fails with libpng's reason and prints nothing") {
  ScratchDir dir("io-png-truncated");
  std::vector<float> values(16 * 16 * 3);
  for (size_t i = 0; i < values.size(); ++i) values[i] = float(i % 7) / 7;
  fs::path whole = dir.file("whole.png"), cut = dir.file("cut.png");
  write_test_image(whole, 16, 16, {"R", "G", "B"}, values);
  std::string bytes = read_bytes(whole);
  std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  std::string error;
  auto input = open_image_file(cut.string(), error, nullptr);
  REQUIRE(input);  // the header is intact
  std::vector<float> pixels(values.size());
  CHECK_FALSE(input->read(3, PixelType::float32, pixels.data()));
  CHECK(input->error() == "Read Error");
  CHECK_FALSE(open_image_file(dir.write("header.png", bytes.substr(0, 20)).string(), error, nullptr));
  CHECK_FALSE(error.empty());
}
