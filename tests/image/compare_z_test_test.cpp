// The Monte-Carlo-aware comparison: Šidák level, z values, and noisy renders of equal and of
// shifted means.
#include <doctest/doctest.h>

#include <cmath>

#include "image/compare.h"
#include "image/compare_test_images.h"
#include "support/test_support.h"

namespace radiant {

using test::run_radiant;
using test::ScratchDir;

TEST_CASE("sidak level is 1 - (1 - alpha)^(1/N) exactly") {
  CHECK(sidak_level(0.01, 12) == doctest::Approx(1 - std::pow(0.99, 1.0 / 12)).epsilon(1e-12));
  CHECK(sidak_level(0.01, 12) == doctest::Approx(8.3716e-4).epsilon(1e-4));
  CHECK(sidak_level(0.05, 1) == doctest::Approx(0.05).epsilon(1e-12));
  // For many tests it approaches alpha/N (Bonferroni) from above.
  double level = sidak_level(0.01, 1000000);
  CHECK(level > 0.01 / 1000000);
  CHECK(level == doctest::Approx(1.00503359e-8).epsilon(1e-7));
}

TEST_CASE("two-sided critical z matches the normal quantiles") {
  CHECK(two_sided_critical_z(0.05) == doctest::Approx(1.959963985).epsilon(1e-9));
  CHECK(two_sided_critical_z(0.01) == doctest::Approx(2.575829304).epsilon(1e-9));
  CHECK(two_sided_critical_z(1e-6) == doctest::Approx(4.891638475).epsilon(1e-9));
}

TEST_CASE("z-test adds both variances and counts a pixel failing on any channel") {
  CompareImage a, b;
  a.path = "a";
  b.path = "b";
  a.width = b.width = 2;
  a.height = b.height = 1;
  a.channel_names = b.channel_names = {"Y"};
  a.values = {1, 1};
  b.values = {1.3f, 2};
  a.variance = {0.01f, 0};
  b.variance = {0.08f, 0.0001f};
  ZTestParams params;
  params.epsilon = 0;
  ZTestResult result = run_z_test(a, b, params);
  CHECK(result.tests == 2);
  CHECK(result.alpha_corrected == doctest::Approx(1 - std::sqrt(0.99)).epsilon(1e-12));
  CHECK(result.abs_z[0] == doctest::Approx(1.0).epsilon(1e-5));    // 0.3 / sqrt(0.09)
  CHECK(result.abs_z[1] == doctest::Approx(100.0).epsilon(1e-5));  // 1 / sqrt(0.0001)
  CHECK(result.max_abs_z == doctest::Approx(100.0).epsilon(1e-5));
  CHECK(result.fail_pixels == 1);
  CHECK(result.fail_fraction == 0.5);
  CHECK(result.verdict == Verdict::fail);
  // The epsilon floor keeps roundoff in noiseless pixels from failing.
  b.values = {1.3f, 1.0000001f};
  params.epsilon = 5e-4;
  CHECK(run_z_test(a, b, params).fail_pixels == 0);
}

namespace {

constexpr int size = 64;
constexpr float sigma = 0.002f;  // standard deviation of each pixel's mean estimate

// A render of the ramp (optionally scaled) with its own noise and a variance AOV of sigma².
void write_render(const std::filesystem::path& path, float scale, unsigned seed) {
  std::vector<float> mean = test::scaled(test::ramp_rgb(size, size), scale);
  test::write_rgb_with_variance(path, size, size, test::with_noise(mean, sigma, seed), sigma * sigma);
}

}  // namespace

TEST_CASE("z-test passes two noisy renders of one mean and fails a 5% shift") {
  ScratchDir dir("compare-mc");
  write_render(dir.file("reference.exr"), 1.0f, 1);
  write_render(dir.file("same.exr"), 1.0f, 2);
  write_render(dir.file("shifted.exr"), 1.05f, 2);
  CompareImage reference = read_compare_image(dir.file("reference.exr").string(), nullptr);
  CompareImage same = read_compare_image(dir.file("same.exr").string(), nullptr);
  CompareImage shifted = read_compare_image(dir.file("shifted.exr").string(), nullptr);
  ZTestResult equal = run_z_test(same, reference, {});
  CHECK(equal.tests == size * size * 3);
  CHECK(equal.alpha_corrected == doctest::Approx(sidak_level(0.01, size * size * 3)));
  CHECK(equal.fail_pixels == 0);
  CHECK(equal.verdict == Verdict::pass);
  // Plain thresholds would not tell noise from bias: the noise alone is over --warn often.
  CHECK(compute_metrics(same, reference, {}).warn_pixels > 0);
  ZTestResult bias = run_z_test(shifted, reference, {});
  CHECK(bias.fail_fraction > 0.5);
  CHECK(bias.verdict == Verdict::fail);

  // Through the CLI the variance AOV switches the z-test on by itself.
  auto compare = [&](const std::string& other, const std::string& flags) {
    return run_radiant("compare '" + dir.file(other).string() + "' '" +
                       dir.file("reference.exr").string() + "' --json " + flags);
  };
  test::CommandResult pass = compare("same.exr", "");
  CHECK(pass.exit_code == 0);
  CHECK(pass.out.find("\"mode\":\"mc\"") != std::string::npos);
  CHECK(pass.out.find("\"tests\":12288") != std::string::npos);
  test::CommandResult fail = compare("shifted.exr", "");
  CHECK(fail.exit_code == 1);
  CHECK(fail.out.find("\"verdict\":\"fail\"") != std::string::npos);
  CHECK(compare("same.exr", "--no-mc").out.find("\"mode\":\"threshold\"") != std::string::npos);
}

TEST_CASE("z-test bias option catches a 1% shift hidden in heavy noise") {
  // Noise ten times the shift per pixel: no single value is significant, their sum is.
  constexpr float heavy = 0.02f;
  std::vector<float> mean = test::ramp_rgb(size, size);
  auto noisy_image = [&](float scale, unsigned seed) {
    CompareImage image;
    image.path = "render";
    image.width = image.height = size;
    image.channel_names = {"R", "G", "B"};
    image.values = test::with_noise(test::scaled(mean, scale), heavy, seed);
    image.variance.assign(image.values.size(), heavy * heavy);
    return image;
  };
  CompareImage reference = noisy_image(1.0f, 4), same = noisy_image(1.0f, 5);
  CompareImage shifted = noisy_image(1.01f, 5);
  ZTestParams params;
  CHECK(run_z_test(shifted, reference, params).verdict != Verdict::fail);
  params.bias_test = true;
  ZTestResult bias = run_z_test(shifted, reference, params);
  CHECK(bias.bias_z > 10);  // expected ≈ 0.005/0.028·√12288 ≈ 19
  CHECK(bias.verdict == Verdict::fail);
  ZTestResult equal = run_z_test(same, reference, params);
  CHECK(std::abs(equal.bias_z) < 2.58);
  CHECK(equal.verdict == Verdict::pass);
}

TEST_CASE("z-test takes a per-sample variance image divided by --spp") {
  ScratchDir dir("compare-mc-spp");
  std::vector<float> mean = test::ramp_rgb(size, size);
  test::write_rgb(dir.file("a.exr"), size, size, test::with_noise(mean, sigma, 3));
  test::write_rgb(dir.file("b.exr"), size, size, mean);
  // 16 samples of per-sample variance 16·sigma² give sigma² for the mean.
  test::write_test_image(dir.file("var.exr"), size, size, {"Y"},
                         std::vector<float>(size * size, 16 * sigma * sigma));
  std::string args = "compare '" + dir.file("a.exr").string() + "' '" +
                     dir.file("b.exr").string() + "' --json --variance '" +
                     dir.file("var.exr").string() + "'";
  test::CommandResult right = run_radiant(args + " --spp 16");
  CHECK(right.exit_code == 0);
  CHECK(right.out.find("\"mode\":\"mc\"") != std::string::npos);
  // Claiming 10000 samples makes the noise look 25 times too large for its variance.
  CHECK(run_radiant(args + " --spp 10000").exit_code == 1);
}

}  // namespace radiant
