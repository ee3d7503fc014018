// The CI gate passes only images a viewer would show alike: a variance no render can have does
// not excuse a difference, an image rotated for display, windowed elsewhere or holding more
// parts than one is refused, and a report that could not be written is an error, not a verdict.
#include <doctest/doctest.h>

#include <sys/wait.h>

#include <cstdlib>

#include "image/compare.h"
#include "image/compare_test_images.h"
#include "image/image_io.h"
#include "output/output_set.h"
#include "support/test_support.h"

namespace radiant {

using test::quoted;
using test::run_radiant;
using test::ScratchDir;

namespace {

CompareImage flat_image(float value, float variance) {
  CompareImage image;
  image.path = "flat.exr";
  image.width = 4, image.height = 4;
  image.channel_names = {"R", "G", "B"};
  image.values.assign(4 * 4 * 3, value);
  if (variance >= 0) image.variance.assign(4 * 4 * 3, variance);
  return image;
}

bool mentions(const test::CommandResult& r, const std::string& text) {
  return r.err.find(text) != std::string::npos || r.out.find(text) != std::string::npos;
}

bool has_oiiotool() { return std::system("command -v oiiotool > /dev/null") == 0; }

}  // namespace

TEST_CASE("compare gate: a finite variance of 3e38 does not pass 0.9 against 0, a plausible one still passes noise") {
  ZTestResult huge = run_z_test(flat_image(0.9f, 3e38f), flat_image(0.0f, -1), ZTestParams{});
  CHECK(huge.implausible_values == 4 * 4 * 3);
  CHECK(huge.verdict == Verdict::fail);
  // A standard deviation of half the value: noisy, but a mean of non-negative samples can have it.
  ZTestResult noisy = run_z_test(flat_image(0.9f, 0.2f), flat_image(0.8f, -1), ZTestParams{});
  CHECK(noisy.implausible_values == 0);
  CHECK(noisy.verdict == Verdict::pass);
  CHECK(first_implausible_variance(flat_image(0.9f, 3e38f), flat_image(0.0f, -1), 4) ==
        "flat.exr: variance.R at (0, 0) is 3e+38, a deviation no mean of 0.9 has (the bound is 7.6)");
}

TEST_CASE("compare gate: the CLI fails an EXR whose variance AOV is 3e38 and says why") {
  ScratchDir dir("compare-huge-variance");
  std::vector<float> claimed;
  for (int i = 0; i < 16; ++i) claimed.insert(claimed.end(), {0.9f, 0.9f, 0.9f, 3e38f, 3e38f, 3e38f});
  test::write_test_image(dir.file("a.exr"), 4, 4, {"R", "G", "B", "variance.R", "variance.G", "variance.B"}, claimed);
  test::write_rgb(dir.file("black.exr"), 4, 4, std::vector<float>(48, 0.0f));
  test::CommandResult r = run_radiant("compare " + quoted(dir.file("a.exr")) + " " + quoted(dir.file("black.exr")));
  CHECK(r.exit_code == 1);
  CHECK(mentions(r, "implausible variance"));
  CHECK(mentions(r, "variance.R at (0, 0) is 3e+38"));
}

TEST_CASE("compare gate: EXR data windows in different places are refused, not compared as the same pixels") {
  ScratchDir dir("compare-windows");
  std::vector<float> values = test::ramp_rgb(4, 4);
  test::write_rgb(dir.file("plain.exr"), 4, 4, values);
  ImageWriteSpec spec;
  spec.width = 4, spec.height = 4, spec.x = 2, spec.full_width = 8, spec.full_height = 4;
  spec.channel_names = {"R", "G", "B"};
  spec.type = PixelType::float32;
  OutputSet outputs;
  write_image_file(outputs.create(dir.file("shifted.exr").string()), spec, values.data());
  outputs.commit();
  test::CommandResult r = run_radiant("compare " + quoted(dir.file("shifted.exr")) + " " + quoted(dir.file("plain.exr")));
  CHECK(r.exit_code == 2);
  CHECK(mentions(r, "image windows differ: " + dir.file("shifted.exr").string() +
                        " has its data window 4x4 at (2, 0) in display window 8x4 at (0, 0)"));
}

TEST_CASE("compare gate: a TIFF with a rotating Orientation and a multi-part EXR are refused") {
  if (!has_oiiotool()) {
    MESSAGE("oiiotool (openimageio-tools) is missing: skipped");
    return;
  }
  ScratchDir dir("compare-orientation");
  test::write_rgb(dir.file("a.exr"), 4, 2, test::ramp_rgb(4, 2));
  test::write_rgb(dir.file("b.exr"), 4, 2, test::scaled(test::ramp_rgb(4, 2), 2));
  std::string a = quoted(dir.file("a.exr"));
  REQUIRE(std::system(("oiiotool " + a + " -d uint8 -o " + quoted(dir.file("a.tif"))).c_str()) == 0);
  REQUIRE(std::system(("oiiotool " + a + " --orientation 6 -d uint8 -o " + quoted(dir.file("turned.tif"))).c_str()) == 0);
  REQUIRE(std::system(("oiiotool " + a + " " + quoted(dir.file("b.exr")) + " --siappend -o " + quoted(dir.file("parts.exr")))
                          .c_str()) == 0);
  test::CommandResult turned = run_radiant("compare " + quoted(dir.file("turned.tif")) + " " + quoted(dir.file("a.tif")));
  CHECK(turned.exit_code == 2);
  CHECK(mentions(turned, "turned.tif: its Orientation 6 flips or rotates it for display"));
  test::CommandResult parts = run_radiant("compare " + quoted(dir.file("parts.exr")) + " " + a);
  CHECK(parts.exit_code == 2);
  CHECK(mentions(parts, "parts.exr: it has more than one part"));
}

TEST_CASE("compare gate: a report that cannot be written (stdout /dev/full) exits 2, not 1") {
  ScratchDir dir("compare-full");
  test::write_rgb(dir.file("a.exr"), 4, 2, test::ramp_rgb(4, 2));
  test::write_rgb(dir.file("b.exr"), 4, 2, test::scaled(test::ramp_rgb(4, 2), 2));
  for (const std::string& b : {"a.exr", "b.exr"}) {  // a pass and a fail: neither is reported
    CAPTURE(b);
    std::string command = "'" RADIANT_EXE "' compare " + quoted(dir.file("a.exr")) + " " + quoted(dir.file(b)) +
                          " > /dev/full 2> " + quoted(dir.file("err.txt"));
    int status = std::system(command.c_str());
    CHECK(WEXITSTATUS(status) == 2);
    CHECK(test::read_bytes(dir.file("err.txt")).find("cannot write the report to standard output") != std::string::npos);
  }
}

}  // namespace radiant
