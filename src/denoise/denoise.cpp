#include "denoise/denoise.h"

#include <tbb/task_arena.h>

#include "denoise/box_filter.h"
#include "denoise/candidate_combine.h"
#include "denoise/feature_prefilter.h"
#include "denoise/regression.h"

namespace radiant {

namespace {

// NL-means bandwidths of the candidates, from trusting the colour to leaning on the features.
const std::vector<float> candidate_bandwidths = {0.5f, 1.0f};

// Per pixel besides the input: the raw and prefiltered features, the smoothed variance, each
// candidate's two halves, its error maps (with the box filter's two planes) and choice maps, and
// the output.
constexpr uint64_t working_pixel_bytes(uint64_t candidates) {
  return 2 * denoise_features_pixel_bytes + sizeof(color3) * 3 +
         candidates * (2 * sizeof(color3) + 5 * sizeof(float)) + sizeof(color3);
}

}  // namespace

uint64_t denoise_bytes(int width, int height, int threads) {
  uint64_t pixels = uint64_t(std::max(width, 0)) * uint64_t(std::max(height, 0));
  uint64_t per_pixel = denoise_input_pixel_bytes + working_pixel_bytes(candidate_bandwidths.size());
  return saturating_add(saturating_multiply(pixels, per_pixel),
                        saturating_multiply(uint64_t(std::max(threads, 1)),
                                            regression_workspace_bytes(int(candidate_bandwidths.size()))));
}

MemoryCharge charge_denoise(MemoryBudget* budget, int width, int height, const std::string& what) {
  return MemoryCharge(budget, denoise_bytes(width, height, tbb::this_task_arena::max_concurrency()),
                      what + ": denoising a " + std::to_string(width) + "x" + std::to_string(height) + " image");
}

std::vector<color3> denoise(const DenoiseInput& in) {
  if (in.color.empty()) return {};
  // A few samples' variance is itself noisy: NL-means reads it smoothed over 3x3 pixels.
  std::vector<color3> variance = box_filter(in.variance, in.width, in.height, 1);
  DenoiseFeatures features = prefilter_features(in);
  std::vector<CandidateImages> candidates = regress_candidates(in, variance, features, candidate_bandwidths);
  return combine_candidates(in, candidates, candidate_errors(in, candidates));
}

std::vector<color3> denoise_film(const Film& film, MemoryBudget* budget, const std::string& what) {
  MemoryCharge charge = charge_denoise(budget, film.width, film.height, what);
  return denoise(denoise_input_from_film(film));
}

}  // namespace radiant
