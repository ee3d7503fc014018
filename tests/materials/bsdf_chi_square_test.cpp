// Chi-square goodness-of-fit tests: the directions Bsdf::sample draws follow Bsdf::pdf
// (the method of pbrt-v4's bsdfs_test.cpp and Mitsuba 3's chi2 tests).
#include <doctest/doctest.h>

#include <algorithm>
#include <functional>

#include "bsdf_test_configs.h"
#include "support/chi_square.h"

namespace radiant::test {
namespace {

constexpr int cos_bins = 10, phi_bins = 20;
constexpr int sample_count = 200000;
constexpr double min_expected_count = 5;  // cells expecting fewer are pooled
constexpr double significance = 0.01;
constexpr float wo_cosines[] = {0.95f, 0.6f, 0.2f};

// Cell of a direction on the (cos theta, phi) grid over the whole sphere.
int cell_of(vec3 w) {
  float c = std::clamp(w.z, -1.0f, 1.0f);
  int i = std::min(int((c + 1) / 2 * cos_bins), cos_bins - 1);
  float phi = std::atan2(w.y, w.x);
  if (phi < 0) phi += 2 * pi;
  int j = std::min(int(phi / (2 * pi) * phi_bins), phi_bins - 1);
  return i * phi_bins + j;
}

std::vector<double> observed_counts(const SurfaceMaterial& m, vec3 wo, unsigned seed) {
  std::vector<double> counts(cos_bins * phi_bins, 0);
  UniformRandom random(seed);
  const Bsdf bsdf(m, {0, 0, 1}, wo);  // built once: its methods are const
  for (int k = 0; k < sample_count; ++k) {
    float u_lobe = random.next();
    vec2 u = random.next2();
    auto s = bsdf.sample(u_lobe, u);
    if (s && !s->delta) counts[cell_of(s->wi)] += 1;
  }
  return counts;
}

constexpr int max_depth = 10, min_depth = 3;

// Adaptive Simpson quadrature with a minimum depth, so narrow peaks are not stepped over.
double simpson(const std::function<double(double)>& f, double a, double b, double fa, double fm, double fb,
               double whole, double eps, int depth) {
  double m = (a + b) / 2, lm = (a + m) / 2, rm = (m + b) / 2;
  double flm = f(lm), frm = f(rm);
  double left = (m - a) / 6 * (fa + 4 * flm + fm), right = (b - m) / 6 * (fm + 4 * frm + fb);
  double delta = left + right - whole;
  bool converged = depth <= max_depth - min_depth && std::abs(delta) <= 15 * eps;
  if (depth <= 0 || converged) return left + right + delta / 15;
  return simpson(f, a, m, fa, flm, fm, left, eps / 2, depth - 1) +
         simpson(f, m, b, fm, frm, fb, right, eps / 2, depth - 1);
}

double integrate(const std::function<double(double)>& f, double a, double b, double eps) {
  double fa = f(a), fm = f((a + b) / 2), fb = f(b);
  return simpson(f, a, b, fa, fm, fb, (b - a) / 6 * (fa + 4 * fm + fb), eps, max_depth);
}

// Expected counts: the pdf integrated over each cell (solid angle = d(cos theta) d(phi)).
std::vector<double> expected_counts(const SurfaceMaterial& m, vec3 wo) {
  std::vector<double> counts(cos_bins * phi_bins, 0);
  const Bsdf bsdf(m, {0, 0, 1}, wo);  // built once: the quadrature evaluates its pdf millions of times
  for (int i = 0; i < cos_bins; ++i) {
    for (int j = 0; j < phi_bins; ++j) {
      double c0 = -1 + 2.0 * i / cos_bins, c1 = -1 + 2.0 * (i + 1) / cos_bins;
      double p0 = 2 * pi * j / phi_bins, p1 = 2 * pi * (j + 1) / phi_bins;
      auto over_phi = [&](double c) {
        auto pdf = [&](double phi) { return double(bsdf.pdf(spherical_direction(float(c), float(phi)))); };
        return integrate(pdf, p0, p1, 1e-8);
      };
      counts[i * phi_bins + j] = integrate(over_phi, c0, c1, 1e-7) * sample_count;
    }
  }
  return counts;
}

void run_chi_square_tests(const std::vector<BsdfConfig>& configs) {
  int test_count = int(non_delta_configs().size() * std::size(wo_cosines));
  double corrected = 1 - std::pow(1 - significance, 1.0 / test_count);  // Sidak
  unsigned seed = 1;
  for (const BsdfConfig& config : configs) {
    for (float cos_wo : wo_cosines) {
      vec3 wo = config_wo(config, cos_wo);
      std::vector<double> observed = observed_counts(config.material, wo, seed++);
      std::vector<double> expected = expected_counts(config.material, wo);
      double p_value = 0;
      std::string failure = chi_square_test(observed, expected, sample_count, min_expected_count, p_value);
      INFO(config.name, ", cos(wo) = ", cos_wo, ", p-value = ", p_value);
      CHECK(failure == "");
      CHECK(p_value > corrected);
    }
  }
}

std::vector<BsdfConfig> configs_of(MaterialModel model) {
  std::vector<BsdfConfig> selected;
  for (const BsdfConfig& config : non_delta_configs())
    if (config.material.model == model) selected.push_back(config);
  return selected;
}

TEST_CASE("chi-square: metallic-roughness sampling follows its pdf") {
  run_chi_square_tests(configs_of(MaterialModel::metallic_roughness));
}

TEST_CASE("chi-square: phong sampling follows its pdf") {
  run_chi_square_tests(configs_of(MaterialModel::phong));
}


}  // namespace
}  // namespace radiant::test
