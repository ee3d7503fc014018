// Accuracy against time: a ladder of renders at growing samples per pixel, each timed and
// measured against a reference, and power-law fits that predict the cost of a target error.
#pragma once

#include <string>
#include <vector>

#include "converge/error_metrics.h"
#include "render/render.h"

namespace radiant {

// -----------------------------------------------------------------------------------------------
// References
// -----------------------------------------------------------------------------------------------

// The converged image a ladder is measured against, with its edge pixels.
struct Reference {
  CompareImage image;
  std::vector<uint8_t> edges;  // edge_mask(image, edge_fraction)
  bool srgb = false;           // read from an 8-bit file: renders are sRGB-encoded to compare
  int spp = 0;                 // samples per pixel it was rendered with (0: read from a file)
  double seconds = 0;          // its render time (0: read from a file)
};

// The fraction of pixels counted as edges (docs/accuracy.md).
constexpr double default_edge_fraction = 0.1;

// The reference renders with a seed of its own, so its noise is independent of the ladder's.
constexpr uint32_t reference_seed_offset = 0x9e3779b9u;

// Renders the reference with `options` at `spp` samples per pixel.
Reference render_reference(const PreparedScene& prepared, RenderOptions options, int spp,
                           double edge_fraction = default_edge_fraction);

// Reads a reference image (EXR compares linear radiance, 8-bit formats sRGB), its pixels charged
// to `budget` for as long as it lives. Throws CompareError or MemoryLimitError.
Reference load_reference(const std::string& path, MemoryBudget* budget, double edge_fraction = default_edge_fraction);

// The mode whose render is the reference of `mode`: path and naive converge to the same answer
// (the path tracer's, which gets there faster); Whitted converges to its own.
RenderMode reference_mode(RenderMode mode);

// -----------------------------------------------------------------------------------------------
// Ladders
// -----------------------------------------------------------------------------------------------

// One rung: a render at `spp` samples per pixel, timed and measured.
struct LadderStep {
  RenderMode mode = RenderMode::path;
  SamplerKind sampler = SamplerKind::jittered;
  int spp = 1;
  bool denoised = false;      // measured on the denoised image (options.denoise)
  double seconds = 0;         // render time (Embree build excluded), the median of the timing runs,
                              // plus the denoiser's time when denoised
  double denoise_seconds = 0;  // the denoiser's part of it
  uint64_t rays = 0;   // rays cast, all kinds
  ErrorMetrics error;
};

// Short renders are timed several times because their time is mostly noise and overhead.
struct TimingPolicy {
  double min_total_seconds = 0.5;  // run again while the runs so far took less than this
  int max_runs = 100;
  int min_runs = 1;  // at least this many runs however long they take (--timing-runs)
};

// 1, 2, 4, ... up to `max_spp` (and `max_spp` itself when it is not a power of two).
std::vector<int> doubling_ladder(int max_spp);

// Renders `options` at `spp` and measures it against `reference` (same size); with
// options.denoise, the denoised image, timed with the denoiser on the render's threads.
LadderStep run_step(const PreparedScene& prepared, RenderOptions options, int spp, const Reference& reference,
                    const TimingPolicy& timing = {});

// run_step for every rung of `ladder`, in order.
std::vector<LadderStep> run_ladder(const PreparedScene& prepared, const RenderOptions& options,
                                   const std::vector<int>& ladder, const Reference& reference,
                                   const TimingPolicy& timing = {});

// -----------------------------------------------------------------------------------------------
// Fits and predictions
// -----------------------------------------------------------------------------------------------

// y = scale · x^exponent, fitted by least squares on log y against log x.
struct PowerFit {
  double scale = 0, exponent = 0;
  int points = 0;  // pairs with x > 0 and y > 0 that took part
};
PowerFit fit_power_law(const std::vector<double>& x, const std::vector<double>& y);

// y = intercept + slope · x, fitted by least squares.
struct LinearFit {
  double intercept = 0, slope = 0;
};
LinearFit fit_line(const std::vector<double>& x, const std::vector<double>& y);

// What reaching an RMSE target costs, extrapolated from a ladder of one mode.
struct Prediction {
  PowerFit error_by_spp;   // RMSE = scale · spp^exponent (Monte Carlo: exponent ≈ −0.5)
  LinearFit seconds_by_spp;  // render time = overhead + per-sample cost · spp
  double spp = 0;          // samples per pixel that reach the target (inf when the fit never does)
  double seconds = 0;      // the render time that takes
};
Prediction predict_target(const std::vector<LadderStep>& steps, double target_rmse);

}  // namespace radiant
