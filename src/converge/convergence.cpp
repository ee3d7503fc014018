#include "converge/convergence.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "denoise/denoise.h"

namespace radiant {

namespace {

bool is_float_image(const CompareImage& image) { return image.color_space != "sRGB"; }

}  // namespace

// -----------------------------------------------------------------------------------------------
// References
// -----------------------------------------------------------------------------------------------

Reference render_reference(const PreparedScene& prepared, RenderOptions options, int spp, double edge_fraction) {
  options.spp = spp;
  options.denoise = false;  // the reference is the converged render itself
  options.seed += reference_seed_offset;
  options.noise_threshold = 0;
  options.time_limit_seconds = 0;
  options.deadline.reset();
  if (options.mode) options.mode = reference_mode(*options.mode);
  RenderResult result = render_prepared(prepared, options);
  Reference reference;
  reference.image = film_to_compare_image(result.film, false);
  reference.image.path = "reference";
  reference.edges = edge_mask(reference.image, edge_fraction);
  reference.spp = spp;
  reference.seconds = result.stats.render_seconds;
  return reference;
}

Reference load_reference(const std::string& path, MemoryBudget* budget, double edge_fraction) {
  Reference reference;
  reference.image = read_compare_image(path, budget);
  CompareImage render_like;  // a render has no alpha: match_alpha drops the reference's
  match_alpha(reference.image, render_like);
  reference.srgb = !is_float_image(reference.image);
  reference.edges = edge_mask(reference.image, edge_fraction);
  return reference;
}

RenderMode reference_mode(RenderMode mode) { return mode == RenderMode::naive ? RenderMode::path : mode; }

// -----------------------------------------------------------------------------------------------
// Ladders
// -----------------------------------------------------------------------------------------------

std::vector<int> doubling_ladder(int max_spp) {
  std::vector<int> ladder;
  for (int spp = 1; spp <= max_spp; spp *= 2) {
    ladder.push_back(spp);
    if (spp > (1 << 29)) break;
  }
  if (ladder.empty() || ladder.back() != max_spp) ladder.push_back(std::max(1, max_spp));
  return ladder;
}

LadderStep run_step(const PreparedScene& prepared, RenderOptions options, int spp, const Reference& reference,
                    const TimingPolicy& timing) {
  options.spp = spp;
  RenderResult result = render_prepared(prepared, options);
  std::vector<double> runs = {result.stats.render_seconds};
  double total = runs.front();
  int most = std::max(timing.min_runs, timing.max_runs);
  for (int run = 1; run < most && (run < timing.min_runs || total < timing.min_total_seconds); ++run) {
    runs.push_back(render_prepared(prepared, options).stats.render_seconds);
    total += runs.back();
  }
  // The median: a run slowed by the machine's other work moves it less than it moves a mean.
  std::sort(runs.begin(), runs.end());
  size_t middle = runs.size() / 2;
  double median = runs.size() % 2 ? runs[middle] : (runs[middle - 1] + runs[middle]) / 2;
  LadderStep step;
  step.mode = result.settings.mode;
  step.sampler = result.settings.sampler;
  step.spp = spp;
  step.seconds = median;
  step.rays = result.stats.rays.total();
  if (!options.denoise) {
    step.error = measure_error(film_to_compare_image(result.film, reference.srgb), reference.image, reference.edges);
    return step;
  }
  std::vector<color3> denoised;
  tbb::task_arena arena(worker_threads(options.threads));
  auto start = std::chrono::steady_clock::now();
  arena.execute([&] { denoised = denoise_film(result.film, options.memory, "converge"); });
  step.denoised = true;
  step.denoise_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  step.seconds += step.denoise_seconds;
  step.error = measure_error(colors_to_compare_image(denoised, result.film.width, result.film.height, reference.srgb),
                             reference.image, reference.edges);
  return step;
}

std::vector<LadderStep> run_ladder(const PreparedScene& prepared, const RenderOptions& options,
                                   const std::vector<int>& ladder, const Reference& reference, const TimingPolicy& timing) {
  std::vector<LadderStep> steps;
  for (int spp : ladder) steps.push_back(run_step(prepared, options, spp, reference, timing));
  return steps;
}

// -----------------------------------------------------------------------------------------------
// Fits and predictions
// -----------------------------------------------------------------------------------------------

LinearFit fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  size_t n = std::min(x.size(), y.size());
  if (n == 0) return {};
  double mean_x = 0, mean_y = 0;
  for (size_t i = 0; i < n; ++i) mean_x += x[i], mean_y += y[i];
  mean_x /= double(n), mean_y /= double(n);
  double covariance = 0, variance = 0;
  for (size_t i = 0; i < n; ++i) {
    covariance += (x[i] - mean_x) * (y[i] - mean_y);
    variance += (x[i] - mean_x) * (x[i] - mean_x);
  }
  LinearFit fit;
  fit.slope = variance > 0 ? covariance / variance : 0;
  fit.intercept = mean_y - fit.slope * mean_x;
  return fit;
}

PowerFit fit_power_law(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> log_x, log_y;
  for (size_t i = 0; i < std::min(x.size(), y.size()); ++i)
    if (x[i] > 0 && y[i] > 0 && std::isfinite(x[i]) && std::isfinite(y[i]))
      log_x.push_back(std::log(x[i])), log_y.push_back(std::log(y[i]));
  LinearFit line = fit_line(log_x, log_y);
  PowerFit fit;
  fit.points = int(log_x.size());
  if (fit.points == 0) return fit;
  fit.exponent = line.slope;
  fit.scale = std::exp(line.intercept);
  return fit;
}

Prediction predict_target(const std::vector<LadderStep>& steps, double target_rmse) {
  std::vector<double> spp, rmse, seconds;
  for (const LadderStep& step : steps) {
    spp.push_back(step.spp);
    rmse.push_back(step.error.rmse);
    seconds.push_back(step.seconds);
  }
  Prediction prediction;
  prediction.error_by_spp = fit_power_law(spp, rmse);
  prediction.seconds_by_spp = fit_line(spp, seconds);
  const PowerFit& fit = prediction.error_by_spp;
  // Error that does not fall with samples (a biased mode, or one rung) never reaches the target.
  if (fit.points < 2 || fit.exponent >= 0 || target_rmse <= 0) {
    prediction.spp = prediction.seconds = std::numeric_limits<double>::infinity();
    return prediction;
  }
  prediction.spp = std::pow(target_rmse / fit.scale, 1 / fit.exponent);
  prediction.seconds = std::max(0.0, prediction.seconds_by_spp.intercept + prediction.seconds_by_spp.slope * prediction.spp);
  return prediction;
}

}  // namespace radiant
