// The view transforms of 8- and 16-bit outputs (src/image/view_transform.h): each curve checked
// against its definition, and the flags, the .scene setting and the bit depths end to end.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>

#include "image/image_io.h"
#include "image/image_writer.h"
#include "image/view_transform.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

float shown(float linear, ViewTransform view, float exposure = 0) {
  return display_encode({linear, linear, linear}, {exposure, view}).x;
}


}  // namespace

TEST_CASE("view transforms: standard is sRGB, linear is the value, exposure is in stops") {
  for (float v : {0.0f, 0.001f, 0.18f, 0.5f, 1.0f}) {
    CHECK(shown(v, ViewTransform::standard) == doctest::Approx(linear_to_srgb(v)));
    CHECK(shown(v, ViewTransform::linear) == doctest::Approx(v));
  }
  CHECK(shown(7, ViewTransform::standard) == doctest::Approx(1.0f));  // clipped
  CHECK(shown(0.1f, ViewTransform::linear, 1) == doctest::Approx(0.2f));
  CHECK(shown(0.4f, ViewTransform::linear, -2) == doctest::Approx(0.1f));
}

TEST_CASE("view transforms: filmic and agx roll highlights off, are monotonic, and keep black black") {
  for (ViewTransform view : {ViewTransform::filmic, ViewTransform::agx}) {
    float previous = -1;
    for (float stops = -10; stops <= 8; stops += 0.25f) {
      float v = shown(0.18f * std::exp2(stops), view);
      CHECK(v >= previous - 1e-5f);  // AgX's polynomial fit wobbles by 1e-6 near white
      previous = v;
    }
    CHECK(shown(0, view) < 0.01f);
    CHECK(shown(1, view) < 0.95f);    // no clipping at 1, unlike standard
    CHECK(shown(64, view) > 0.97f);   // but bright values still approach white
  }
  // Narkowicz's fit at 1: (2.51 + 0.03) / (2.43 + 0.59 + 0.14), sRGB-encoded.
  CHECK(shown(1, ViewTransform::filmic) == doctest::Approx(linear_to_srgb(2.54f / 3.16f)).epsilon(1e-5));
  // AgX puts middle grey near the middle of the display range, and keeps grey grey.
  CHECK(shown(0.18f, ViewTransform::agx) == doctest::Approx(0.50).epsilon(0.03));
  color3 grey = display_encode({0.3f, 0.3f, 0.3f}, {0, ViewTransform::agx});
  CHECK(grey.x == doctest::Approx(grey.y).epsilon(1e-3));
  CHECK(grey.y == doctest::Approx(grey.z).epsilon(1e-3));
}

TEST_CASE("view transforms: the flags, the .scene setting, 16-bit PNG and half EXR, and their refusals") {
  ScratchDir dir("view-flags");
  const std::string plane =  // lit to about 0.25: inside [0, 1], where every view differs
      "@camera\nposition 0 4 0\ndirection 0 -1 0\nup 0 0 -1\northographic 2\n"
      "@light directional\ndirection 0 -1 0\ncolor 64 64 64\n"
      "@plane\npoint 0 0 0\nnormal 0 1 0\nkd 1\n";
  fs::path scene = dir.write("s.scene", plane);
  std::string render = "render " + quoted(scene) + " --width 8 --height 8 --spp 1 --quiet -o ";
  auto center = [](const fs::path& file) {
    std::string error;
    auto image = open_image_file(file.string(), error, nullptr);
    REQUIRE_MESSAGE(image, error);
    std::vector<float> pixels(8 * 8 * 3);
    REQUIRE_MESSAGE(image->read(3, PixelType::float32, pixels.data()), image->error());
    return pixels[(4 * 8 + 4) * 3];
  };
  REQUIRE(run_radiant(render + quoted(dir.file("standard.png"))).exit_code == 0);
  REQUIRE(run_radiant(render + quoted(dir.file("linear.png")) + " --view linear").exit_code == 0);
  REQUIRE(run_radiant(render + quoted(dir.file("dark.png")) + " --view linear --exposure -1").exit_code == 0);
  REQUIRE(run_radiant(render + quoted(dir.file("deep.png")) + " --bit-depth 16").exit_code == 0);
  // No metadata: the sizes compare the pixels' storage, not the command lines and times recorded.
  REQUIRE(run_radiant(render + quoted(dir.file("half.exr")) + " --half --no-metadata").exit_code == 0);
  REQUIRE(run_radiant(render + quoted(dir.file("full.exr")) + " --no-metadata").exit_code == 0);
  float linear = center(dir.file("full.exr"));
  REQUIRE(linear > 0.05f);
  REQUIRE(linear < 0.9f);
  CHECK(center(dir.file("linear.png")) == doctest::Approx(linear).epsilon(0.01));
  CHECK(center(dir.file("dark.png")) == doctest::Approx(linear / 2).epsilon(0.02));
  CHECK(center(dir.file("standard.png")) == doctest::Approx(linear_to_srgb(linear)).epsilon(0.01));
  CHECK(center(dir.file("deep.png")) == doctest::Approx(linear_to_srgb(linear)).epsilon(1e-4));  // 16 bits
  CHECK(center(dir.file("half.exr")) == doctest::Approx(linear).epsilon(1e-3));
  CHECK(fs::file_size(dir.file("half.exr")) < fs::file_size(dir.file("full.exr")));
  // The scene's own setting, which a flag overrides.
  fs::path classic = dir.write("classic.scene", plane + "@render\nview linear\n");
  REQUIRE(run_radiant("render " + quoted(classic) + " --width 8 --height 8 --spp 1 --quiet -o " + quoted(dir.file("c.png"))).exit_code == 0);
  CHECK(same_pixels(dir.file("c.png"), dir.file("linear.png")));
  CommandResult bad = run_radiant(render + quoted(dir.file("x.png")) + " --view vivid");
  CHECK(bad.exit_code == 2);
  CHECK(bad.err.find("unknown view 'vivid' (standard, linear, filmic or agx)") != std::string::npos);
  CHECK(run_radiant(render + quoted(dir.file("x.png")) + " --half").exit_code == 2);
  CHECK(run_radiant(render + quoted(dir.file("x.jpg")) + " --bit-depth 16").exit_code == 2);
  CHECK(run_radiant(render + quoted(dir.file("x.png")) + " --bit-depth 12").exit_code == 2);
  CHECK_FALSE(fs::exists(dir.file("x.png")));
}
