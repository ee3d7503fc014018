// The convergence library: metrics against a reference, power-law fits, and the Monte Carlo
// rate a ladder measures on a scene with indirect light.
#include <doctest/doctest.h>

#include <cmath>

#include "converge/convergence.h"
#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

CompareImage gray_image(int width, int height, std::vector<float> gray) {
  CompareImage image;
  image.width = width, image.height = height;
  image.channel_names = {"R", "G", "B"};
  for (float v : gray) image.values.insert(image.values.end(), {v, v, v});
  return image;
}

// A diffuse sphere on a diffuse floor under a uniform sky: every pixel is noisy in path mode.
SceneDesc sphere_on_floor() {
  SceneDesc scene;
  int gray = add_diffuse(scene, {0.7f, 0.7f, 0.7f});
  add_plane(scene, {0, -1, 0}, {0, 1, 0}, gray);
  add_sphere(scene, {0, 0, 0}, 1, gray);
  scene.cameras.push_back(perspective_camera({0, 1.5f, 4}, normalize(vec3{0, -0.5f, -1}), {0, 1, 0}, 50));
  return scene;
}

}  // namespace

TEST_CASE("converge: relative MSE is the mean of (a-b)^2/(b^2+0.01) over pixels and channels") {
  CompareImage reference = gray_image(2, 1, {0.0f, 1.0f});
  CompareImage image = gray_image(2, 1, {0.1f, 1.5f});
  // (0.01 / 0.01 + 0.25 / 1.01) / 2 over both pixels, the same in each channel.
  CHECK(relative_mse(image, reference) == doctest::Approx((1.0 + 0.25 / 1.01) / 2));
  ErrorMetrics error = measure_error(image, reference, {});
  CHECK(error.rmse == doctest::Approx(std::sqrt((0.01 + 0.25) / 2)).epsilon(1e-5));
  CHECK(error.psnr == doctest::Approx(-20 * std::log10(error.rmse)).epsilon(1e-4));
  CHECK(error.edge_rmse == 0);
}

TEST_CASE("converge: the edge mask marks the top fraction of pixels by Sobel gradient, and edge RMSE counts only them") {
  // 10x1 rows of 10: a vertical step from 0 to 1 between columns 4 and 5.
  std::vector<float> gray;
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x) gray.push_back(x < 5 ? 0.0f : 1.0f);
  CompareImage reference = gray_image(10, 10, gray);
  std::vector<uint8_t> edges = edge_mask(reference, 0.2);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x) CHECK(edges[y * 10 + x] == (x == 4 || x == 5 ? 1 : 0));
  CompareImage image = reference;
  for (int y = 0; y < 10; ++y) {
    for (int c = 0; c < 3; ++c) image.values[(y * 10 + 4) * 3 + c] = 0.5f;  // an edge pixel off by 0.5
    for (int c = 0; c < 3; ++c) image.values[(y * 10 + 0) * 3 + c] = 0.2f;  // a flat pixel off by 0.2
  }
  CHECK(masked_rmse(image, reference, edges) == doctest::Approx(0.5 / std::sqrt(2.0)));
  CHECK(measure_error(image, reference, edges).edge_rmse == doctest::Approx(0.5 / std::sqrt(2.0)));
}

TEST_CASE("converge: power-law and line fits recover exact laws, predictions invert them") {
  std::vector<double> spp = {1, 4, 16, 64}, rmse, seconds;
  for (double n : spp) rmse.push_back(0.3 * std::pow(n, -0.5)), seconds.push_back(0.01 + 0.002 * n);
  PowerFit fit = fit_power_law(spp, rmse);
  CHECK(fit.exponent == doctest::Approx(-0.5));
  CHECK(fit.scale == doctest::Approx(0.3));
  CHECK(fit.points == 4);
  LinearFit line = fit_line(spp, seconds);
  CHECK(line.intercept == doctest::Approx(0.01));
  CHECK(line.slope == doctest::Approx(0.002));

  std::vector<LadderStep> steps;
  for (size_t i = 0; i < spp.size(); ++i) {
    LadderStep step;
    step.spp = int(spp[i]);
    step.seconds = seconds[i];
    step.error.rmse = rmse[i];
    steps.push_back(step);
  }
  Prediction p = predict_target(steps, 0.01);  // 0.3 / sqrt(n) = 0.01 at n = 900
  CHECK(p.spp == doctest::Approx(900));
  CHECK(p.seconds == doctest::Approx(0.01 + 0.002 * 900));
  for (LadderStep& step : steps) step.error.rmse = 0.05;  // a biased mode: error flat in spp
  CHECK(std::isinf(predict_target(steps, 0.01).spp));
}

TEST_CASE("converge: the default ladder doubles up to --max-spp and ends on it") {
  CHECK(doubling_ladder(256) == std::vector<int>{1, 2, 4, 8, 16, 32, 64, 128, 256});
  CHECK(doubling_ladder(100) == std::vector<int>{1, 2, 4, 8, 16, 32, 64, 100});
  CHECK(doubling_ladder(1) == std::vector<int>{1});
  CHECK(reference_mode(RenderMode::naive) == RenderMode::path);
  CHECK(reference_mode(RenderMode::whitted) == RenderMode::whitted);
}

TEST_CASE("converge: path-traced RMSE falls as spp^-1/2 along the ladder (random sampler)") {
  SceneDesc scene = sphere_on_floor();
  PreparedScene prepared = prepare_scene(scene);
  RenderOptions options;
  options.width = options.height = 24;
  options.mode = RenderMode::path;
  options.sampler = SamplerKind::random;
  options.env_color = color3{1, 1, 1};
  options.max_depth = 4;
  Reference reference = render_reference(prepared, options, 2048);
  CHECK(reference.spp == 2048);
  std::vector<LadderStep> steps = run_ladder(prepared, options, {1, 2, 4, 8, 16, 32, 64}, reference, {0, 1});
  REQUIRE(steps.size() == 7);
  for (size_t i = 1; i < steps.size(); ++i) CHECK(steps[i].error.rmse < steps[i - 1].error.rmse);
  CHECK(steps.back().rays > steps.front().rays * 32);
  Prediction fit = predict_target(steps, 0.001);
  CHECK(fit.error_by_spp.exponent >= -0.65);
  CHECK(fit.error_by_spp.exponent <= -0.35);
}
