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

color3 srgb(color3 c) { return {linear_to_srgb(c.x), linear_to_srgb(c.y), linear_to_srgb(c.z)}; }

void check_close(color3 actual, color3 expected, double epsilon) {
  for (int i = 0; i < 3; ++i) CHECK(actual[i] == doctest::Approx(expected[i]).epsilon(epsilon));
}

// three.js's ACESFilmicToneMapping as published (tonemapping_pars_fragment): its GLSL mat3s are
// given by columns, so this multiplies column by column, independently of radiant's row layout.
color3 three_js_aces(color3 c) {
  const color3 input_columns[3] = {{0.59719f, 0.07600f, 0.02840f}, {0.35458f, 0.90834f, 0.13383f}, {0.04823f, 0.01566f, 0.83777f}};
  const color3 output_columns[3] = {{1.60475f, -0.10208f, -0.00327f}, {-0.53108f, 1.10813f, -0.07276f},
                                    {-0.07367f, -0.00605f, 1.07602f}};
  auto fit = [](float v) { return (v * (v + 0.0245786f) - 0.000090537f) / (v * (0.983729f * v + 0.4329510f) + 0.238081f); };
  c = c * (1 / 0.6f);
  c = input_columns[0] * c.x + input_columns[1] * c.y + input_columns[2] * c.z;
  c = {fit(c.x), fit(c.y), fit(c.z)};
  c = output_columns[0] * c.x + output_columns[1] * c.y + output_columns[2] * c.z;
  return min(max(c, {0, 0, 0}), {1, 1, 1});
}

// A plane lit to about 0.25: inside [0, 1], where every view differs.
const std::string lit_plane =
    "@camera\nposition 0 4 0\ndirection 0 -1 0\nup 0 0 -1\northographic 2\n"
    "@light directional\ndirection 0 -1 0\ncolor 64 64 64\n"
    "@plane\npoint 0 0 0\nnormal 0 1 0\nkd 1\n";

// The centre pixel's first channel of an 8x8 image.
float center(const fs::path& file) {
  std::string error;
  auto image = open_image_file(file.string(), error, nullptr);
  REQUIRE_MESSAGE(image, error);
  std::vector<float> pixels(8 * 8 * 3);
  REQUIRE_MESSAGE(image->read(3, PixelType::float32, pixels.data()), image->error());
  return pixels[(4 * 8 + 4) * 3];
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

TEST_CASE("view transforms: filmic, agx, neutral and aces roll highlights off, are monotonic, and keep black black") {
  for (ViewTransform view : {ViewTransform::filmic, ViewTransform::agx, ViewTransform::neutral, ViewTransform::aces}) {
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

TEST_CASE("view transforms: neutral is Khronos PBR Neutral") {
  // Below the start of compression (peak 0.76 after the offset) colours pass unchanged, less the
  // offset 0.04 once the darkest channel reaches 0.08 ...
  check_close(display_encode({0.5f, 0.3f, 0.1f}, {0, ViewTransform::neutral}), srgb({0.46f, 0.26f, 0.06f}), 1e-5);
  check_close(display_encode({0.79f, 0.5f, 0.6f}, {0, ViewTransform::neutral}), srgb({0.75f, 0.46f, 0.56f}), 1e-5);
  // ... and less x - x^2 / 0.16 below that (x the darkest channel), so black stays black.
  float offset = 0.05f - 0.05f * 0.05f / 0.16f;
  check_close(display_encode({0.05f, 0.2f, 0.6f}, {0, ViewTransform::neutral}),
              srgb({0.05f - offset, 0.2f - offset, 0.6f - offset}), 1e-5);
  CHECK(shown(0, ViewTransform::neutral) == 0);
  // Above it the peak p becomes 1 - 0.24^2 / (p + 0.24 - 0.76), and the colour is mixed towards
  // that grey by 1 - 1 / (0.15 (p - new peak) + 1): grey 1 (p = 0.96) ...
  CHECK(shown(1, ViewTransform::neutral) == doctest::Approx(linear_to_srgb(1 - 0.0576f / 0.44f)).epsilon(1e-5));
  // ... and (2, 1, 0.5), whose peak 1.96 becomes 0.96, mixed by 0.15 / 1.15.
  float scale = 0.96f / 1.96f / 1.15f, grey = 0.96f * (0.15f / 1.15f);
  check_close(display_encode({2, 1, 0.5f}, {0, ViewTransform::neutral}),
              srgb({1.96f * scale + grey, 0.96f * scale + grey, 0.46f * scale + grey}), 1e-5);
  // The output never reaches 1, however bright (standard clips at 1).
  for (float v : {1.0f, 10.0f, 1000.0f}) {
    color3 c = display_encode({v, v * 0.5f, v * 0.1f}, {0, ViewTransform::neutral});
    CHECK(max_component(c) < 1);
  }
  CHECK(shown(1000, ViewTransform::neutral) > 0.9999f);
}

TEST_CASE("view transforms: aces is three.js's ACESFilmicToneMapping") {
  CHECK(shown(0, ViewTransform::aces) == 0);
  // Grey stays grey (every row of both matrices sums to 1): 0.18 / 0.6 = 0.3 through the fit.
  float fit = (0.3f * (0.3f + 0.0245786f) - 0.000090537f) / (0.3f * (0.983729f * 0.3f + 0.4329510f) + 0.238081f);
  CHECK(shown(0.18f, ViewTransform::aces) == doctest::Approx(linear_to_srgb(fit)).epsilon(1e-4));
  for (color3 c : {color3{1, 0.2f, 0.05f}, color3{0.02f, 0.3f, 0.9f}, color3{4, 2.5f, 0.7f}})
    check_close(display_encode(c, {0, ViewTransform::aces}), srgb(three_js_aces(c)), 1e-5);
  // Its matrices mix channels: a bright saturated blue turns purple (red above green), as in three.js.
  color3 blue = display_encode({0.02f, 0.05f, 2}, {0, ViewTransform::aces});
  CHECK(blue.x > blue.y);
  check_close(blue, srgb(three_js_aces({0.02f, 0.05f, 2})), 1e-5);
}

TEST_CASE("view transforms: neutral and aces render, differ from standard where bright, and survive a shard's metadata") {
  ScratchDir dir("view-tone");
  fs::path scene = dir.write("s.scene", lit_plane);
  // Three stops up the plane is at about 2: standard clips it, the tone mappers do not.
  std::string render = "render " + quoted(scene) + " --width 8 --height 8 --spp 1 --quiet --exposure 3 -o ";
  REQUIRE(run_radiant(render + quoted(dir.file("standard.png"))).exit_code == 0);
  REQUIRE(run_radiant(render + quoted(dir.file("neutral.png")) + " --view neutral").exit_code == 0);
  REQUIRE(run_radiant(render + quoted(dir.file("aces.png")) + " --view aces").exit_code == 0);
  REQUIRE(run_radiant(render + quoted(dir.file("linear.exr"))).exit_code == 0);
  float linear = center(dir.file("linear.exr")) * 8;
  REQUIRE(linear > 1.2f);
  CHECK(center(dir.file("standard.png")) == 1);
  CHECK(center(dir.file("neutral.png")) < 0.99f);
  CHECK(center(dir.file("neutral.png")) == doctest::Approx(shown(linear, ViewTransform::neutral)).epsilon(0.01));
  CHECK(center(dir.file("aces.png")) == doctest::Approx(shown(linear, ViewTransform::aces)).epsilon(0.01));
  // The .scene setting, and a shard's radiant:view read back by merge.
  fs::path chosen = dir.write("neutral.scene", lit_plane + "@render\nview neutral\n");
  REQUIRE(run_radiant("render " + quoted(chosen) + " --width 8 --height 8 --spp 1 --quiet --exposure 3 -o " +
                      quoted(dir.file("chosen.png"))).exit_code == 0);
  CHECK(same_pixels(dir.file("chosen.png"), dir.file("neutral.png")));
  REQUIRE(run_radiant(render + quoted(dir.file("shard.exr")) + " --view aces --shard 0/1").exit_code == 0);
  CommandResult info = run_radiant("info " + quoted(dir.file("shard.exr")));
  CHECK(info.out.find("aces") != std::string::npos);
  REQUIRE(run_radiant("merge " + quoted(dir.file("shard.exr")) + " --quiet -o " + quoted(dir.file("merged.png"))).exit_code == 0);
  CHECK(same_pixels(dir.file("merged.png"), dir.file("aces.png")));
}

TEST_CASE("view transforms: the flags, the .scene setting, 16-bit PNG and half EXR, and their refusals") {
  ScratchDir dir("view-flags");
  const std::string& plane = lit_plane;
  fs::path scene = dir.write("s.scene", plane);
  std::string render = "render " + quoted(scene) + " --width 8 --height 8 --spp 1 --quiet -o ";
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
  CHECK(bad.err.find("unknown view 'vivid' (standard, linear, filmic, agx, neutral or aces)") != std::string::npos);
  CHECK(run_radiant(render + quoted(dir.file("x.png")) + " --half").exit_code == 2);
  CHECK(run_radiant(render + quoted(dir.file("x.jpg")) + " --bit-depth 16").exit_code == 2);
  CHECK(run_radiant(render + quoted(dir.file("x.png")) + " --bit-depth 12").exit_code == 2);
  CHECK_FALSE(fs::exists(dir.file("x.png")));
}
