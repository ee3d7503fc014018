#include "denoise/candidate_combine.h"

#include <tbb/parallel_for.h>

#include "denoise/box_filter.h"

namespace radiant {

namespace {

constexpr int error_smoothing_radius = 3;
constexpr int choice_smoothing_radius = 2;

color3 candidate_mean(const CandidateImages& c, size_t i) { return (c.even[i] + c.odd[i]) * 0.5f; }

}  // namespace

std::vector<std::vector<float>> candidate_errors(const DenoiseInput& in, const std::vector<CandidateImages>& candidates) {
  size_t count = in.color.size();
  std::vector<std::vector<float>> errors;
  for (const CandidateImages& candidate : candidates) {
    std::vector<float> variance(count), excess(count);
    tbb::parallel_for(size_t(0), count, [&](size_t i) {
      // Relative to the most smoothing candidate's brightness, the same for every candidate.
      float scale = luminance(candidate_mean(candidates.back(), i));
      float relative = 1 / (scale * scale + 1e-2f);
      color3 mean = candidate_mean(candidate, i);
      float v = 0, e = 0;
      for (int c = 0; c < 3; ++c) {
        float half_difference = candidate.even[i][c] - candidate.odd[i][c];
        float half_variance = half_difference * half_difference / 4;  // the variance of their mean
        float difference = mean[c] - in.color[i][c];
        v += half_variance;
        e += difference * difference - in.variance[i][c] - half_variance;
      }
      variance[i] = v * relative, excess[i] = e * relative;
    });
    variance = box_filter(variance, in.width, in.height, error_smoothing_radius);
    excess = box_filter(excess, in.width, in.height, error_smoothing_radius);
    for (size_t i = 0; i < count; ++i) variance[i] += std::max(0.0f, excess[i]);
    errors.push_back(std::move(variance));
  }
  return errors;
}

std::vector<color3> combine_candidates(const DenoiseInput& in, const std::vector<CandidateImages>& candidates,
                                       const std::vector<std::vector<float>>& errors) {
  size_t count = in.color.size();
  std::vector<std::vector<float>> chosen(candidates.size(), std::vector<float>(count, 0.0f));
  for (size_t i = 0; i < count; ++i) {
    size_t best = 0;
    for (size_t c = 1; c < candidates.size(); ++c)
      if (errors[c][i] < errors[best][i]) best = c;
    chosen[best][i] = 1;
  }
  for (std::vector<float>& choice : chosen) choice = box_filter(choice, in.width, in.height, choice_smoothing_radius);
  std::vector<color3> out(count);
  tbb::parallel_for(size_t(0), count, [&](size_t i) {
    color3 sum{};
    float weight = 0;
    for (size_t c = 0; c < candidates.size(); ++c) {
      sum += chosen[c][i] * candidate_mean(candidates[c], i);
      weight += chosen[c][i];
    }
    out[i] = sum / weight;
  });
  return out;
}

}  // namespace radiant
