// Discrete and piecewise-constant distributions for importance sampling.
#pragma once

#include <cstddef>
#include <vector>

#include "math/vec.h"

namespace radiant {

// A discrete distribution over weights (negative or non-finite weights count as zero).
struct Distribution1D {
  std::vector<float> cdf;  // size n + 1, cdf[0] = 0, cdf[n] = 1
  std::vector<float> pmf;
  float total = 0;
  size_t size() const { return pmf.size(); }
  bool empty() const { return total <= 0; }
};

Distribution1D make_distribution(const std::vector<float>& weights);
// Index with probability pmf[i]; `remapped` receives u rescaled to [0,1) within the bucket.
size_t sample_discrete(const Distribution1D& d, float u, float* remapped = nullptr);

// A piecewise-constant 2D density on [0,1)^2 over a width x height grid (row-major weights).
struct Distribution2D {
  int width = 0, height = 0;
  std::vector<Distribution1D> rows;  // conditional p(u | v)
  Distribution1D marginal;           // p(v)
};

Distribution2D make_distribution_2d(const std::vector<float>& weights, int width, int height);
// Samples (u, v) in [0,1)^2 and returns its density with respect to area in [0,1)^2.
vec2 sample_continuous_2d(const Distribution2D& d, vec2 u, float& pdf);
float continuous_2d_pdf(const Distribution2D& d, vec2 uv);

}  // namespace radiant
