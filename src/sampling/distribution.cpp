#include "sampling/distribution.h"

#include <algorithm>
#include <cmath>

namespace radiant {

Distribution1D make_distribution(const std::vector<float>& weights) {
  Distribution1D d;
  size_t n = weights.size();
  d.pmf.resize(n);
  d.cdf.assign(n + 1, 0.0f);
  double total = 0;
  for (size_t i = 0; i < n; ++i) total += (std::isfinite(weights[i]) && weights[i] > 0) ? weights[i] : 0.0;
  d.total = float(total);
  if (total <= 0) return d;
  double running = 0;
  for (size_t i = 0; i < n; ++i) {
    double w = (std::isfinite(weights[i]) && weights[i] > 0) ? weights[i] : 0.0;
    d.pmf[i] = float(w / total);
    running += w;
    d.cdf[i + 1] = float(running / total);
  }
  d.cdf[n] = 1;
  return d;
}

size_t sample_discrete(const Distribution1D& d, float u, float* remapped) {
  size_t n = d.pmf.size();
  // The last bucket whose cdf start is <= u, skipping zero-probability buckets.
  size_t i = size_t(std::upper_bound(d.cdf.begin(), d.cdf.end(), u) - d.cdf.begin());
  i = std::clamp<size_t>(i == 0 ? 0 : i - 1, 0, n - 1);
  while (i + 1 < n && d.pmf[i] == 0) ++i;
  while (i > 0 && d.pmf[i] == 0) --i;
  if (remapped) *remapped = d.pmf[i] > 0 ? std::min((u - d.cdf[i]) / d.pmf[i], 0x1.fffffep-1f) : 0.0f;
  return i;
}

Distribution2D make_distribution_2d(const std::vector<float>& weights, int width, int height) {
  Distribution2D d;
  d.width = width;
  d.height = height;
  std::vector<float> row_totals(height);
  for (int y = 0; y < height; ++y) {
    std::vector<float> row(weights.begin() + size_t(y) * width, weights.begin() + size_t(y + 1) * width);
    d.rows.push_back(make_distribution(row));
    row_totals[y] = d.rows.back().total;
  }
  d.marginal = make_distribution(row_totals);
  return d;
}

vec2 sample_continuous_2d(const Distribution2D& d, vec2 u, float& pdf) {
  float uy, ux;
  size_t y = sample_discrete(d.marginal, u.y, &uy);
  size_t x = sample_discrete(d.rows[y], u.x, &ux);
  pdf = d.marginal.pmf[y] * d.rows[y].pmf[x] * float(d.width) * float(d.height);
  return {(float(x) + ux) / float(d.width), (float(y) + uy) / float(d.height)};
}

float continuous_2d_pdf(const Distribution2D& d, vec2 uv) {
  int x = std::clamp(int(uv.x * d.width), 0, d.width - 1);
  int y = std::clamp(int(uv.y * d.height), 0, d.height - 1);
  if (d.marginal.empty()) return 0;
  return d.marginal.pmf[y] * d.rows[y].pmf[x] * float(d.width) * float(d.height);
}

}  // namespace radiant
