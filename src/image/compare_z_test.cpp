// The Monte-Carlo-aware comparison: a two-sided z-test per value with a Šidák-corrected level.
#include <algorithm>
#include <cmath>
#include <limits>

#include "image/compare.h"

namespace radiant {

namespace {

// The value's z: values that do not differ give 0, any other non-finite pair +inf.
double signed_z(double a, double b, double variance, double epsilon) {
  if (same_value(a, b)) return 0;
  if (!std::isfinite(a) || !std::isfinite(b)) return std::numeric_limits<double>::infinity();
  double floor = epsilon * (1 + (std::abs(a) + std::abs(b)) / 2);
  return (a - b) / std::sqrt(variance + floor * floor);
}

// Whether `image`'s own variance (if any) of value `i` is plausible for its value.
bool plausible_side(const CompareImage& image, size_t i, const ZTestParams& params) {
  return image.variance.empty() || plausible_variance(image.values[i], image.variance[i], params.max_relative_deviation);
}

double two_sided_p_value(double abs_z) { return std::erfc(abs_z / std::sqrt(2.0)); }

Verdict z_test_verdict(const ZTestResult& result, const ZTestParams& params) {
  bool biased = params.bias_test && result.bias_p_value < params.alpha;
  if (result.nonfinite_values > 0 || result.implausible_values > 0 || result.fail_fraction * 100 > params.allowed_fail_percent || biased)
    return Verdict::fail;
  return result.fail_pixels > 0 ? Verdict::warn : Verdict::pass;
}

}  // namespace

double sidak_level(double alpha, size_t tests) {
  // 1 − (1 − alpha)^(1/tests) without losing digits when the result is tiny.
  return -std::expm1(std::log1p(-alpha) / double(tests));
}

double two_sided_critical_z(double p) {
  double low = 0, high = 40;  // erfc(40/√2) underflows doubles: every p > 0 lies inside
  for (int i = 0; i < 200; ++i) {
    double middle = (low + high) / 2;
    (two_sided_p_value(middle) > p ? low : high) = middle;
  }
  return (low + high) / 2;
}

ZTestResult run_z_test(const CompareImage& a, const CompareImage& b, const ZTestParams& params) {
  int channels = a.channels();
  ZTestResult result;
  result.tests = a.values.size();
  result.alpha_corrected = sidak_level(params.alpha, result.tests);
  result.z_critical = two_sided_critical_z(result.alpha_corrected);
  result.abs_z.assign(a.pixel_count(), 0.0f);
  double z_sum = 0;
  size_t finite_count = 0;
  for (size_t p = 0; p < a.pixel_count(); ++p) {
    bool failed = false;
    for (int c = 0; c < channels; ++c) {
      size_t i = p * channels + c;
      double variance = (a.variance.empty() ? 0.0 : a.variance[i]) +
                        (b.variance.empty() ? 0.0 : b.variance[i]);
      if (!std::isfinite(variance) || nonfinite_difference(a.values[i], b.values[i]))
        result.nonfinite_values += 1;
      else if (!plausible_side(a, i, params) || !plausible_side(b, i, params))
        result.implausible_values += 1;
      double z_signed = signed_z(a.values[i], b.values[i], variance > 0 ? variance : 0.0,
                                 params.epsilon);
      if (std::isfinite(z_signed)) {
        z_sum += z_signed;
        finite_count += 1;
      }
      double z = std::abs(z_signed);
      double p_value = two_sided_p_value(z);
      failed = failed || p_value < result.alpha_corrected;
      result.max_abs_z = std::max(result.max_abs_z, z);
      result.min_p_value = std::min(result.min_p_value, p_value);
      result.abs_z[p] = std::max(result.abs_z[p], float(z));
    }
    result.fail_pixels += failed ? 1 : 0;
  }
  result.fail_fraction = double(result.fail_pixels) / double(a.pixel_count());
  result.bias_z = finite_count > 0 ? z_sum / std::sqrt(double(finite_count)) : 0;
  result.bias_p_value = two_sided_p_value(std::abs(result.bias_z));
  result.verdict = z_test_verdict(result, params);
  return result;
}

}  // namespace radiant
