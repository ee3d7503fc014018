// Chi-square goodness of fit of sampled counts against expected counts (the method of pbrt-v4's
// bsdfs_test.cpp and Mitsuba 3's chi2 tests), shared by the BSDF and light-selection tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace radiant::test {

// Upper tail of the chi-square distribution (Wilson-Hilferty normal approximation).
inline double chi_square_p_value(double statistic, int dof) {
  double k = dof, z = (std::cbrt(statistic / k) - (1 - 2 / (9 * k))) / std::sqrt(2 / (9 * k));
  return 0.5 * std::erfc(z / std::sqrt(2.0));
}

// Pools cells expecting fewer than `min_expected_count` (pbrt's rule), then sets the p-value of
// `observed` (out of `sample_count` samples) against `expected`; returns "" or a failure reason.
inline std::string chi_square_test(const std::vector<double>& observed, const std::vector<double>& expected,
                                   double sample_count, double min_expected_count, double& p_value) {
  std::vector<int> order(observed.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = int(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return expected[a] < expected[b]; });
  double statistic = 0, pooled_observed = 0, pooled_expected = 0;
  int dof = 0, pooled_cells = 0;
  for (int cell : order) {
    if (expected[cell] == 0) {
      if (observed[cell] > sample_count * 1e-5) return "samples in a cell of zero probability";
    } else if (expected[cell] < min_expected_count ||
               (pooled_cells > 0 && pooled_expected < min_expected_count)) {
      pooled_observed += observed[cell], pooled_expected += expected[cell], ++pooled_cells;
    } else {
      double d = observed[cell] - expected[cell];
      statistic += d * d / expected[cell], ++dof;
    }
  }
  if (pooled_cells > 0) {
    double d = pooled_observed - pooled_expected;
    statistic += d * d / pooled_expected, ++dof;
  }
  dof -= 1;
  if (dof < 1) return "too few cells";
  p_value = chi_square_p_value(statistic, dof);
  return "";
}

}  // namespace radiant::test
