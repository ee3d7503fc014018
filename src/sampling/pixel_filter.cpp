#include "sampling/pixel_filter.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "scene/enum_names.h"

namespace radiant {

namespace {

constexpr float gaussian_sigma = 0.5f;
constexpr float mitchell_b = 1.0f / 3, mitchell_c = 1.0f / 3;
constexpr int cells_per_pixel_of_radius = 32;  // pbrt-v4's FilterSampler

float gaussian(float x) {
  return std::exp(-x * x / (2 * gaussian_sigma * gaussian_sigma)) / std::sqrt(2 * pi * gaussian_sigma * gaussian_sigma);
}

// Mitchell and Netravali's cubic on [-2, 2] (pbrt-v4's Mitchell1D).
float mitchell(float x) {
  const float b = mitchell_b, c = mitchell_c;
  x = std::abs(x);
  if (x <= 1) return ((12 - 9 * b - 6 * c) * x * x * x + (-18 + 12 * b + 6 * c) * x * x + (6 - 2 * b)) / 6;
  if (x <= 2) return ((-b - 6 * c) * x * x * x + (6 * b + 30 * c) * x * x + (-12 * b - 48 * c) * x + (8 * b + 24 * c)) / 6;
  return 0;
}

// The four-term Blackman-Harris window over [-1, 1].
float blackman_harris(float t) {
  if (std::abs(t) >= 1) return 0;
  float phase = 2 * pi * (t + 1) / 2;
  return 0.35875f - 0.48829f * std::cos(phase) + 0.14128f * std::cos(2 * phase) - 0.01168f * std::cos(3 * phase);
}

bool tabulated(PixelFilterKind kind) {
  return kind != PixelFilterKind::box && kind != PixelFilterKind::triangle;
}

// Offset from the pixel centre of a tent of `radius` (pbrt-v4's SampleTent).
float sample_tent(float u, float radius) {
  if (u < 0.5f) return -radius + radius * std::sqrt(2 * u);
  return radius - radius * std::sqrt(2 - 2 * u);
}

// One axis's position from the pixel's corner; multiplies `weight` by the axis's weight.
float sample_axis(const PixelFilter& f, float u, float& weight) {
  switch (f.kind) {
    case PixelFilterKind::box: return u * (2 * f.radius) + (0.5f - f.radius);  // u itself at radius 0.5
    case PixelFilterKind::triangle: return 0.5f + sample_tent(u, f.radius);
    case PixelFilterKind::gaussian:
    case PixelFilterKind::mitchell:
    case PixelFilterKind::blackman_harris: break;
  }
  float within = 0;
  size_t cell = sample_discrete(f.table, u, &within);
  weight *= f.cell_weights[cell];
  float cell_width = 2 * f.radius / float(f.table.size());
  return 0.5f - f.radius + (float(cell) + within) * cell_width;
}

}  // namespace

float default_filter_radius(PixelFilterKind kind) {
  switch (kind) {
    case PixelFilterKind::box: return 0.5f;
    case PixelFilterKind::gaussian: return 1.5f;
    case PixelFilterKind::triangle:
    case PixelFilterKind::mitchell:
    case PixelFilterKind::blackman_harris: return 2;
  }
  return 0.5f;
}

float eval_filter_1d(PixelFilterKind kind, float radius, float x) {
  if (std::abs(x) > radius) return 0;
  switch (kind) {
    case PixelFilterKind::box: return 1;
    case PixelFilterKind::triangle: return radius - std::abs(x);
    case PixelFilterKind::gaussian: return std::max(0.0f, gaussian(x) - gaussian(radius));
    case PixelFilterKind::mitchell: return mitchell(2 * x / radius);
    case PixelFilterKind::blackman_harris: return blackman_harris(x / radius);
  }
  return 0;
}

PixelFilter make_pixel_filter(PixelFilterKind kind, float radius) {
  if (!(radius > 0 && radius <= max_filter_width / 2))
    throw std::invalid_argument("a filter width must be in (0, " + std::to_string(int(max_filter_width)) + "] pixels");
  PixelFilter filter;
  filter.kind = kind;
  filter.radius = radius;
  if (!tabulated(kind)) return filter;
  int cells = std::max(1, int(cells_per_pixel_of_radius * radius));
  std::vector<float> values(size_t(cells), 0.0f), magnitudes(size_t(cells), 0.0f);
  double signed_sum = 0, magnitude_sum = 0;
  for (int i = 0; i < cells; ++i) {
    float centre = -radius + 2 * radius * (float(i) + 0.5f) / float(cells);
    values[size_t(i)] = eval_filter_1d(kind, radius, centre);
    magnitudes[size_t(i)] = std::abs(values[size_t(i)]);
    signed_sum += values[size_t(i)], magnitude_sum += magnitudes[size_t(i)];
  }
  filter.table = make_distribution(magnitudes);
  // f / pdf over the filter's integral: sign(f) * sum |f| / sum f, exactly 1 where f is positive
  // everywhere (both sums are then the same additions).
  float magnitude = float(magnitude_sum / signed_sum);
  filter.cell_weights.resize(size_t(cells));
  for (int i = 0; i < cells; ++i)
    filter.cell_weights[size_t(i)] = values[size_t(i)] > 0 ? magnitude : values[size_t(i)] < 0 ? -magnitude : 0.0f;
  return filter;
}

FilterSample sample_filter(const PixelFilter& filter, vec2 u) {
  FilterSample s;
  s.position.x = sample_axis(filter, u.x, s.weight);
  s.position.y = sample_axis(filter, u.y, s.weight);
  return s;
}

float sample_filter_pdf_1d(const PixelFilter& filter, float x) {
  float r = filter.radius;
  if (!(std::abs(x) < r)) return 0;
  switch (filter.kind) {
    case PixelFilterKind::box: return 1 / (2 * r);
    case PixelFilterKind::triangle: return (r - std::abs(x)) / (r * r);
    case PixelFilterKind::gaussian:
    case PixelFilterKind::mitchell:
    case PixelFilterKind::blackman_harris: break;
  }
  size_t cells = filter.table.size();
  size_t cell = std::min(cells - 1, size_t((x + r) / (2 * r) * float(cells)));
  return filter.table.pmf[cell] * float(cells) / (2 * r);
}

const char* pixel_filter_name(PixelFilterKind kind) { return name_of(pixel_filter_names, kind); }

PixelFilterKind parse_pixel_filter(const std::string& name) {
  if (std::optional<PixelFilterKind> kind = value_named(pixel_filter_names, name)) return *kind;
  throw std::invalid_argument("unknown filter '" + name + "' (" + names_text(pixel_filter_names) + ")");
}

}  // namespace radiant
