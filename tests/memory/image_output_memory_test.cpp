// Writing TIFF or JPEG loads OpenImageIO, whose libraries and buffers add about 124 MiB to the
// process: --max-memory charges them (image/image_writer.h image_module_bytes) before the render,
// so a TIFF render under the cap stays within the cap plus the baseline of a PNG render.
#include <doctest/doctest.h>

#include <filesystem>

#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

constexpr uint64_t MiB = uint64_t(1) << 20;

MeasuredRun render_first(const ScratchDir& dir, const std::string& output, int size, const std::string& cap) {
  return run_radiant_measured("render " + quoted(source_path("assets/first-render.scene")) + " -o " +
                              quoted(dir.file(output)) + " --width " + std::to_string(size) + " --height " +
                              std::to_string(size) + " --spp 1 -q --max-memory " + cap);
}

}  // namespace

TEST_CASE("memory: a TIFF or JPEG output whose writer does not fit beside the render is refused before rendering") {
  ScratchDir dir("image-output-memory");
  // 600x600 fits 64 MiB as a PNG; with OpenImageIO's 128 MiB charged it cannot.
  MeasuredRun png = render_first(dir, "out.png", 600, "0.0625");
  CHECK(png.result.exit_code == 0);
  for (const char* name : {"out.tif", "out.jpg"}) {
    CAPTURE(name);
    MeasuredRun run = render_first(dir, name, 600, "0.0625");
    CAPTURE(run.result.err);
    CHECK(run.result.exit_code == 1);
    CHECK(run.result.err.find(std::string(name) + ": OpenImageIO's libraries and buffers to write it: 128 MiB needed") !=
          std::string::npos);
    CHECK(run.result.err.find("over the memory limit of 64.0 MiB (--max-memory)") != std::string::npos);
    CHECK(!fs::exists(dir.file(name)));
  }
}

TEST_CASE("memory: a TIFF render under --max-memory peaks within the cap plus a PNG render's baseline") {
  ScratchDir dir("image-output-memory");
  MeasuredRun baseline = render_first(dir, "baseline.png", 8, "0.25");
  REQUIRE(baseline.result.exit_code == 0);
  // 900x900: the film and image (about 110 MiB) and OpenImageIO (128 MiB) fit 256 MiB.
  MeasuredRun run = render_first(dir, "out.tif", 900, "0.25");
  CAPTURE(run.result.err);
  REQUIRE(run.result.exit_code == 0);
  CHECK(fs::exists(dir.file("out.tif")));
  if (built_with_address_sanitizer) return;  // resident memory there is the sanitizer's
  uint64_t bound = 256 * MiB + baseline.peak_rss_bytes + 16 * MiB;
  CAPTURE(run.peak_rss_bytes / MiB);
  CAPTURE(bound / MiB);
  CHECK(run.peak_rss_bytes <= bound);
}
