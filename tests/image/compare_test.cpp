// The plain comparison metrics against hand-computed values, channel matching and the defaults.
#include <doctest/doctest.h>

#include "image/compare.h"
#include "image/compare_test_images.h"
#include "image/false_color.h"
#include "support/test_support.h"

namespace radiant {

using test::ScratchDir;

namespace {

CompareImage image_from(const std::string& name, int width, int height, std::vector<float> values) {
  CompareImage image;
  image.path = name;
  image.width = width;
  image.height = height;
  image.channel_names = {"R", "G", "B"};
  image.values = std::move(values);
  return image;
}

// 2×2: B differs from A by 0.1 (pixel 1, R), 0.04 (pixel 2, B) and 0.01 (pixel 3, G).
CompareImage two_by_two_a() {
  return image_from("a", 2, 2, {0.5f, 0.5f, 0.5f, 0.2f, 0.2f, 0.2f, 1, 1, 1, 0, 0, 0});
}
CompareImage two_by_two_b() {
  return image_from("b", 2, 2, {0.5f, 0.5f, 0.5f, 0.3f, 0.2f, 0.2f, 1, 1, 0.96f, 0, 0.01f, 0});
}

}  // namespace

TEST_CASE("compare metrics on a 2x2 image match hand-computed values") {
  CompareThresholds thresholds;
  thresholds.fail = 0.05;
  thresholds.warn = 0.005;
  CompareMetrics m = compute_metrics(two_by_two_a(), two_by_two_b(), thresholds);
  CHECK(m.pixels == 4);
  CHECK(m.channels == 3);
  CHECK(m.mean_error == doctest::Approx(0.15 / 12).epsilon(1e-6));
  CHECK(m.rmse == doctest::Approx(std::sqrt((0.01 + 0.0016 + 0.0001) / 12)).epsilon(1e-6));
  CHECK(m.psnr == doctest::Approx(20 * std::log10(1 / std::sqrt(0.0117 / 12))).epsilon(1e-6));
  CHECK(m.max_error == doctest::Approx(0.1).epsilon(1e-6));
  CHECK(m.max_x == 1);
  CHECK(m.max_y == 0);
  CHECK(m.max_channel == 0);
  // Σ|a−b| = 0.15 over the mean level (Σa + Σb)/2 = (5.1 + 5.17)/2.
  CHECK(m.mean_relative_error == doctest::Approx(0.15 / 5.135).epsilon(1e-6));
  CHECK(m.fail_pixels == 1);  // only the 0.1 difference is over 0.05
  CHECK(m.fail_fraction == 0.25);
  CHECK(m.warn_pixels == 3);  // 0.1, 0.04 and 0.01 are over 0.005
  CHECK(m.warn_fraction == 0.75);
  CHECK(threshold_verdict(m, thresholds) == Verdict::fail);
}

TEST_CASE("compare metrics of identical images are zero with an infinite PSNR") {
  CompareMetrics m = compute_metrics(two_by_two_a(), two_by_two_a(), {});
  CHECK(m.rmse == 0);
  CHECK(m.max_error == 0);
  CHECK(m.mean_relative_error == 0);
  CHECK(std::isinf(m.psnr));
  CHECK(threshold_verdict(m, {}) == Verdict::pass);
}

TEST_CASE("mean relative error of a 4x1 image scaled by 1.05 is 0.05/1.025 whatever it shows") {
  CompareImage a = image_from("a", 4, 1, {0, 0, 0, 0.01f, 0.01f, 0.01f, 0.5f, 0.5f, 0.5f, 2, 2, 2});
  CompareImage b = a;
  b.values = test::scaled(a.values, 1.05f);
  CompareMetrics m = compute_metrics(a, b, {});
  CHECK(m.mean_relative_error == doctest::Approx(0.05 / 1.025).epsilon(1e-5));
  CHECK(m.max_error == doctest::Approx(0.1).epsilon(1e-5));
  CHECK(m.fail_pixels == 2);  // 0.5 and 2 move by more than 0.02 (0.025 and 0.1)
}

TEST_CASE("default thresholds fail a whole image 5% brighter and pass tiny noise") {
  CompareImage a = image_from("a", 32, 32, test::ramp_rgb(32, 32));
  CompareImage brighter = a, noisy = a;
  brighter.values = test::scaled(a.values, 1.05f);
  noisy.values = test::with_noise(a.values, 0.001f, 7);
  CompareThresholds defaults;
  CompareMetrics bright = compute_metrics(a, brighter, defaults);
  CHECK(bright.mean_relative_error == doctest::Approx(0.05 / 1.025).epsilon(1e-5));
  CHECK(threshold_verdict(bright, defaults) == Verdict::fail);
  CompareMetrics noise = compute_metrics(a, noisy, defaults);
  CHECK(noise.fail_pixels == 0);
  CHECK(noise.mean_relative_error < 0.002);
  CHECK(threshold_verdict(noise, defaults) == Verdict::pass);
  // Dim images too: the relative error does not depend on the level.
  CompareImage dim = a, dim_brighter = a;
  dim.values = test::scaled(a.values, 0.05f);
  dim_brighter.values = test::scaled(dim.values, 1.05f);
  CHECK(threshold_verdict(compute_metrics(dim, dim_brighter, defaults), defaults) == Verdict::fail);
}

TEST_CASE("compare reads R,G,B by name, ignores AOVs and takes alpha only when both have it") {
  ScratchDir dir("compare-channels");
  // EXR stores channels sorted by name (A,B,G,R,Z): selection must go by name, not position.
  test::write_test_image(dir.file("aov.exr"), 2, 1, {"R", "G", "B", "A", "Z"},
                         {0.1f, 0.2f, 0.3f, 1, 9, 0.4f, 0.5f, 0.6f, 0.5f, 9});
  CompareImage rgba = read_compare_image(dir.file("aov.exr").string(), nullptr);
  CHECK(rgba.channel_names == std::vector<std::string>{"R", "G", "B", "A"});
  CHECK(rgba.values == std::vector<float>{0.1f, 0.2f, 0.3f, 1, 0.4f, 0.5f, 0.6f, 0.5f});
  CHECK(rgba.color_channels() == 3);
  CHECK(rgba.variance.empty());
  test::write_rgb(dir.file("rgb.png"), 2, 1, {0, 0, 0, 1, 1, 1});
  CompareImage png = read_compare_image(dir.file("rgb.png").string(), nullptr);
  CHECK_FALSE(png.has_alpha);
  CHECK(png.values == std::vector<float>{0, 0, 0, 1, 1, 1});
  // Alpha only when both have it.
  CompareImage both = rgba;
  match_alpha(rgba, both);
  CHECK(rgba.channels() == 4);
  match_alpha(rgba, png);
  CHECK(rgba.channel_names == std::vector<std::string>{"R", "G", "B"});
  CHECK(rgba.values == std::vector<float>{0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f});
  CHECK_FALSE(rgba.has_alpha);
}

TEST_CASE("compare reads the variance AOV by channel name") {
  ScratchDir dir("compare-variance");
  test::write_rgb_with_variance(dir.file("v.exr"), 2, 1, {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f},
                                0.25f);
  CompareImage image = read_compare_image(dir.file("v.exr").string(), nullptr);
  CHECK(image.values == std::vector<float>{0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f});
  CHECK(image.variance == std::vector<float>(6, 0.25f));
  // A separate per-sample variance image is divided by the sample count.
  test::write_test_image(dir.file("var.exr"), 2, 1, {"Y"}, {8, 16});
  CHECK(read_variance_image(dir.file("var.exr").string(), image, 4, nullptr) ==
        std::vector<float>{2, 2, 2, 4, 4, 4});
  test::write_test_image(dir.file("small.exr"), 1, 1, {"Y"}, {8});
  CHECK_THROWS_WITH_AS(read_variance_image(dir.file("small.exr").string(), image, 4, nullptr),
                       (dir.file("small.exr").string() + ": variance image is 1x1 but " +
                        dir.file("v.exr").string() + " is 2x1")
                           .c_str(),
                       CompareError);
}

TEST_CASE("compare refuses images of different sizes or channel counts with one clear line") {
  CompareImage a = two_by_two_a();
  CompareImage wide = image_from("wide", 4, 1, a.values);
  CHECK_THROWS_WITH_AS(check_comparable(a, wide), "image sizes differ: a is 2x2, wide is 4x1",
                       CompareError);
  CompareImage gray = a;
  gray.path = "gray";
  gray.channel_names = {"Y"};
  CHECK_THROWS_WITH_AS(check_comparable(a, gray),
                       "channel counts differ: a has 3 compared channels, gray has 1",
                       CompareError);
}

TEST_CASE("false color ramp runs black, red, yellow, white") {
  auto same = [](color3 c, color3 expected) {
    return c.x == expected.x && c.y == expected.y && c.z == expected.z;
  };
  CHECK(same(false_color(0), {0, 0, 0}));
  CHECK(same(false_color(1.0f / 3), {1, 0, 0}));
  CHECK(same(false_color(2.0f / 3), {1, 1, 0}));
  CHECK(same(false_color(1), {1, 1, 1}));
  CHECK(same(false_color(7), {1, 1, 1}));
  CHECK(same(false_color(-1), {0, 0, 0}));
  CHECK(same(false_color(std::nanf("")), {1, 1, 1}));
}

}  // namespace radiant

namespace radiant {

TEST_CASE("compare fails a NaN against a number and passes NaN against NaN and equal infinities") {
  CompareImage a;
  a.path = "a";
  a.width = 2;
  a.height = 1;
  a.channel_names = {"Y"};
  a.values = {0.5f, INFINITY};
  CompareImage nan = a;
  nan.values = {NAN, INFINITY};
  CompareMetrics m = compute_metrics(a, nan, {});
  CHECK(m.fail_pixels == 1);
  CHECK(threshold_verdict(m, {}) == Verdict::fail);
  CHECK(std::isinf(pixel_max_difference(a, nan)[0]));
  CHECK(pixel_max_difference(a, nan)[1] == 0);
  CompareMetrics same = compute_metrics(nan, nan, {});
  CHECK(same.fail_pixels == 0);
  CHECK(threshold_verdict(same, {}) == Verdict::pass);
  CHECK(pixel_max_difference(nan, nan) == std::vector<float>{0, 0});
  nan.variance = {0.01f, 0.01f};
  CHECK(run_z_test(nan, nan, {}).max_abs_z == 0);
  CHECK(run_z_test(a, nan, {}).fail_pixels == 1);
}

TEST_CASE("compare fails a NaN or infinity facing another value whatever the thresholds") {
  // One such pixel in a thousand is under --fail-percent, but no noise explains it.
  CompareImage a;
  a.path = "a";
  a.width = 1000;
  a.height = 1;
  a.channel_names = {"Y"};
  a.values.assign(1000, 0.5f);
  for (float bad : {NAN, INFINITY}) {
    CompareImage b = a;
    b.path = "b";
    b.values[7] = bad;
    CompareMetrics m = compute_metrics(a, b, {});
    CHECK(m.nonfinite_pixels == 1);
    CHECK(threshold_verdict(m, {}) == Verdict::fail);
    CHECK(first_nonfinite(a, b) == "b: Y at (7, 0) is " + std::string(std::isnan(bad) ? "nan" : "inf") +
                                       " where a has 0.5");
    b.variance.assign(1000, 0.01f);
    ZTestResult z = run_z_test(a, b, {});
    CHECK(z.nonfinite_values == 1);
    CHECK(z.verdict == Verdict::fail);
  }
  CHECK(first_nonfinite(a, a).empty());
}

TEST_CASE("z-test fails a non-finite variance: 0.9 against 0.0 cannot pass as noise") {
  CompareImage a, b;
  a.path = "a.exr";
  b.path = "b.exr";
  a.width = b.width = 4;
  a.height = b.height = 1;
  a.channel_names = b.channel_names = {"R"};
  a.values.assign(4, 0.9f);
  b.values.assign(4, 0.0f);
  a.variance.assign(4, INFINITY);
  ZTestResult z = run_z_test(a, b, {});
  CHECK(z.nonfinite_values == 4);
  CHECK(z.verdict == Verdict::fail);
  CHECK(first_nonfinite(a, b) == "a.exr: variance.R at (0, 0) is inf");
  // NaN too, and even identical values: the statistic itself is broken.
  a.variance.assign(4, 0.0f);
  a.variance[2] = NAN;
  CHECK(run_z_test(a, a, {}).verdict == Verdict::fail);
  CHECK(first_nonfinite(a, b) == "a.exr: variance.R at (2, 0) is nan");
  a.variance[2] = 0.01f;
  CHECK(first_nonfinite(a, b).empty());
}

}  // namespace radiant
