// `radiant compare` through the executable: exit codes, messages, --json, --diff.
#include <doctest/doctest.h>

#include <cstdlib>
#include <fstream>

#include "image/compare.h"
#include "image/compare_test_images.h"
#include "support/test_support.h"

namespace radiant {

using test::quoted;
using test::run_radiant;
using test::ScratchDir;

namespace {


// The number after "key": in a flat JSON text (enough for checking our own output).
double json_value(const std::string& json, const std::string& key) {
  size_t at = json.find("\"" + key + "\":");
  REQUIRE_MESSAGE(at != std::string::npos, key);
  return std::strtod(json.c_str() + at + key.size() + 3, nullptr);
}

// Writes a.exr (a ramp), same.exr (a copy), bright.exr (×1.05) and small.exr (another size).
struct ComparePair {
  ScratchDir dir{"compare-cli"};
  std::filesystem::path a = dir.file("a.exr"), same = dir.file("same.exr"),
                        bright = dir.file("bright.exr"), small = dir.file("small.exr");
  ComparePair() {
    test::write_rgb(a, 8, 4, test::ramp_rgb(8, 4));
    test::write_rgb(same, 8, 4, test::ramp_rgb(8, 4));
    test::write_rgb(bright, 8, 4, test::scaled(test::ramp_rgb(8, 4), 1.05f));
    test::write_rgb(small, 4, 4, test::ramp_rgb(4, 4));
  }
  std::string args(const std::filesystem::path& other, const std::string& flags = "") const {
    return "compare " + quoted(a) + " " + quoted(other) + (flags.empty() ? "" : " " + flags);
  }
};

}  // namespace

TEST_CASE("radiant compare exits 0 for identical images and 1 for a 5% brighter one") {
  ComparePair pair;
  test::CommandResult same = run_radiant(pair.args(pair.same));
  CHECK(same.exit_code == 0);
  CHECK(same.out.find("verdict: pass") != std::string::npos);
  CHECK(same.err.empty());
  test::CommandResult bright = run_radiant(pair.args(pair.bright));
  CHECK(bright.exit_code == 1);
  CHECK(bright.out.find("verdict: fail") != std::string::npos);
  // Loose enough thresholds let the same pair pass.
  CHECK(run_radiant(pair.args(pair.bright, "--fail 0.1 --fail-relative 0.1")).exit_code == 0);
}

TEST_CASE("radiant compare exits 2 with one clear line on size mismatch, bad files and flags") {
  ComparePair pair;
  test::CommandResult size = run_radiant(pair.args(pair.small));
  CHECK(size.exit_code == 2);
  CHECK(size.out.empty());
  CHECK(size.err == "radiant compare: image sizes differ: " + pair.a.string() + " is 8x4, " +
                        pair.small.string() + " is 4x4\n");
  std::filesystem::path garbage = pair.dir.write("garbage.exr", "not an image");
  test::CommandResult unreadable = run_radiant(pair.args(garbage));
  CHECK(unreadable.exit_code == 2);
  CHECK(unreadable.err.rfind("radiant compare: " + garbage.string() + ": cannot read image", 0) == 0);
  CHECK(run_radiant(pair.args(pair.dir.file("missing.png"))).exit_code == 2);
  test::CommandResult flag = run_radiant(pair.args(pair.same, "--bogus"));
  CHECK(flag.exit_code == 2);
  CHECK(flag.err.find("--bogus") != std::string::npos);
  CHECK(run_radiant(pair.args(pair.same, "--fail -1")).exit_code == 2);
  test::CommandResult nan = run_radiant(pair.args(pair.same, "--fail nan"));
  CHECK(nan.exit_code == 2);
  CHECK(nan.err == "radiant compare: --fail: must be a number in [0, 1e+30], not nan\n");
  CHECK(run_radiant(pair.args(pair.same, "--alpha 0")).exit_code == 2);
  CHECK(run_radiant(pair.args(pair.same, "--variance v.exr")).exit_code == 2);  // needs --spp
  CHECK(run_radiant("compare " + quoted(pair.a)).exit_code == 2);
  test::CommandResult no_variance = run_radiant(pair.args(pair.same, "--mc"));
  CHECK(no_variance.exit_code == 2);
  CHECK(no_variance.err.find("--mc needs a variance") != std::string::npos);
}

TEST_CASE("radiant compare refuses, in one line, an image whose decoding needs more than --max-memory") {
  ComparePair pair;
  std::filesystem::path bomb = test::source_path("tests/fuzz/regressions/image/timeout-exr-data-window-4m-wide-in-683-bytes.exr");
  test::CommandResult refused = run_radiant("compare " + quoted(bomb) + " " + quoted(pair.a) + " --max-memory 0.25");
  CHECK(refused.exit_code == 2);
  CHECK(refused.out.empty());
  CHECK(refused.err == "radiant compare: " + bomb.string() + ": OpenEXR's buffers for its declared chunks: 567 MiB needed, over "
                       "the memory limit of 256 MiB (--max-memory)\n");
  // The same images within the limit compare as before.
  CHECK(run_radiant(pair.args(pair.same, "--max-memory 0.25")).exit_code == 0);
}

TEST_CASE("radiant compare --json prints one object whose numbers match the metrics") {
  ComparePair pair;
  test::CommandResult result = run_radiant(pair.args(pair.bright, "--json"));
  CHECK(result.exit_code == 1);
  const std::string& json = result.out;
  REQUIRE(!json.empty());
  CHECK(json.front() == '{');
  CHECK(json.find('\n') == json.size() - 1);  // one line, nothing else on stdout
  CHECK(json.substr(json.size() - 2) == "}\n");
  CHECK(json.find("\"verdict\":\"fail\"") != std::string::npos);
  CHECK(json.find("\"mode\":\"threshold\"") != std::string::npos);
  CHECK(json.find("\"channels\":[\"R\",\"G\",\"B\"]") != std::string::npos);
  CHECK(json.find("\"z_test\":null") != std::string::npos);
  CompareImage a = read_compare_image(pair.a.string(), nullptr);
  CompareImage b = read_compare_image(pair.bright.string(), nullptr);
  CompareMetrics m = compute_metrics(a, b, {});
  CHECK(json_value(json, "rmse") == doctest::Approx(m.rmse).epsilon(1e-8));
  CHECK(json_value(json, "psnr") == doctest::Approx(m.psnr).epsilon(1e-8));
  CHECK(json_value(json, "max_error") == doctest::Approx(m.max_error).epsilon(1e-8));
  CHECK(json_value(json, "mean_error") == doctest::Approx(m.mean_error).epsilon(1e-8));
  CHECK(json_value(json, "mean_relative_error") == doctest::Approx(0.05 / 1.025).epsilon(1e-5));
  CHECK(json_value(json, "fail_pixels") == double(m.fail_pixels));
  CHECK(json_value(json, "fail_fraction") == doctest::Approx(m.fail_fraction));
  CHECK(json_value(json, "fail") == 0.02);

  test::CommandResult same = run_radiant(pair.args(pair.same, "--json"));
  CHECK(same.exit_code == 0);
  CHECK(same.out.find("\"psnr\":null") != std::string::npos);  // +inf is not JSON
  CHECK(same.out.find("\"verdict\":\"pass\"") != std::string::npos);
}

TEST_CASE("radiant compare warns on stderr when a linear EXR meets an sRGB PNG") {
  ComparePair pair;
  std::filesystem::path png = pair.dir.file("a.png");
  test::write_rgb(png, 8, 4, test::ramp_rgb(8, 4));
  test::CommandResult result = run_radiant(pair.args(png, "--json"));
  CHECK(result.exit_code == 0);  // the same numbers up to 8-bit rounding
  CHECK(result.err == "radiant compare: warning: " + pair.a.string() + " is Linear but " +
                          png.string() + " is sRGB; the metrics compare the files' own encodings\n");
  CHECK(result.out.find("\"verdict\"") != std::string::npos);
}

TEST_CASE("radiant compare --diff writes a false-color image of the inputs' size, none on error") {
  ComparePair pair;
  std::filesystem::path diff = pair.dir.file("diff.png");
  CHECK(run_radiant(pair.args(pair.bright, "--diff " + quoted(diff) + " --diff-scale 0.04"))
            .exit_code == 1);
  test::TestImage image = test::read_image(diff);
  CHECK(image.width == 8);
  CHECK(image.height == 4);
  CHECK(image.channels == 3);
  // Pixel (0,0) differs by at most 0.05·0.292 = 0.0146 (0.37 of the scale: red); pixel (7,3) by
  // 0.05·0.754 = 0.0377 (0.94 of it: nearly white).
  CHECK(image.at(0, 0, 0) == 1);
  CHECK(image.at(0, 0, 1) == doctest::Approx(0.096).epsilon(0.1));
  CHECK(image.at(0, 0, 2) == 0);
  CHECK(image.at(7, 3, 1) == 1);
  CHECK(image.at(7, 3, 2) == doctest::Approx(0.83).epsilon(0.05));

  std::filesystem::path none = pair.dir.file("none.exr");
  CHECK(run_radiant(pair.args(pair.small, "--diff " + quoted(none))).exit_code == 2);
  CHECK_FALSE(std::filesystem::exists(none));
  test::CommandResult bad = run_radiant(pair.args(pair.same, "--diff " + quoted(pair.dir.file("x.nosuchformat"))));
  CHECK(bad.exit_code == 2);
  CHECK(bad.err.find("x.nosuchformat") != std::string::npos);
  int files = 0;
  for (auto& entry : std::filesystem::directory_iterator(pair.dir.path)) files += entry.is_regular_file();
  CHECK(files == 5);  // the four inputs and diff.png: no temporary left behind
}

TEST_CASE("radiant compare fails, saying why, when a variance is infinite") {
  // A render whose variance overflowed would pass any image as noise: 0.9 against 0.0.
  ScratchDir dir("compare-nonfinite");
  std::filesystem::path render = dir.file("render.exr"), black = dir.file("black.exr");
  test::write_rgb_with_variance(render, 2, 2, std::vector<float>(12, 0.9f), INFINITY);
  test::write_rgb(black, 2, 2, std::vector<float>(12, 0.0f));
  test::CommandResult table = run_radiant("compare " + quoted(render) + " " + quoted(black));
  CHECK(table.exit_code == 1);
  CHECK(table.out.find("\n  non-finite           " + render.string() +
                       ": variance.R at (0, 0) is inf: fails whatever the thresholds\n") != std::string::npos);
  CHECK(table.out.find("verdict: fail") != std::string::npos);
  test::CommandResult json = run_radiant("compare " + quoted(render) + " " + quoted(black) + " --json");
  CHECK(json.exit_code == 1);
  CHECK(json.out.find("\"nonfinite\":\"" + render.string() + ": variance.R at (0, 0) is inf\"") !=
        std::string::npos);
  CHECK(json.out.find("\"verdict\":\"fail\"") != std::string::npos);
  // Plain thresholds do not read the variance; the z-test refuses it even against itself.
  CHECK(run_radiant("compare " + quoted(render) + " " + quoted(render) + " --no-mc").exit_code == 0);
  CHECK(run_radiant("compare " + quoted(render) + " " + quoted(render)).exit_code == 1);
}

TEST_CASE("radiant compare: a truncated PNG is one line on stderr, without libpng's own") {
  ComparePair pair;
  std::filesystem::path png = pair.dir.file("a.png"), cut = pair.dir.file("cut.png");
  test::write_rgb(png, 8, 4, test::ramp_rgb(8, 4));
  std::string bytes = test::read_bytes(png);
  std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() - 20);
  test::CommandResult r = run_radiant("compare " + quoted(png) + " " + quoted(cut));
  CHECK(r.exit_code == 2);
  CHECK(r.err == "radiant compare: " + cut.string() + ": cannot read pixels: Read Error\n");
}

}  // namespace radiant
