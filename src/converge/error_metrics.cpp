#include "converge/error_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "image/image_writer.h"

namespace radiant {

namespace {

float pixel_luminance(const CompareImage& image, int x, int y) {
  x = std::clamp(x, 0, image.width - 1);
  y = std::clamp(y, 0, image.height - 1);
  const float* v = &image.values[(size_t(y) * image.width + x) * image.channels()];
  if (image.color_channels() < 3) return v[0];
  return luminance({v[0], v[1], v[2]});
}

float sobel_magnitude(const CompareImage& image, int x, int y) {
  auto l = [&](int dx, int dy) { return pixel_luminance(image, x + dx, y + dy); };
  float gx = (l(1, -1) + 2 * l(1, 0) + l(1, 1)) - (l(-1, -1) + 2 * l(-1, 0) + l(-1, 1));
  float gy = (l(-1, 1) + 2 * l(0, 1) + l(1, 1)) - (l(-1, -1) + 2 * l(0, -1) + l(1, -1));
  return std::sqrt(gx * gx + gy * gy);
}

}  // namespace

CompareImage colors_to_compare_image(const std::vector<color3>& colors, int width, int height, bool srgb) {
  CompareImage image;
  image.path = "render";
  image.width = width;
  image.height = height;
  image.channel_names = {"R", "G", "B"};
  image.color_space = srgb ? "sRGB" : "Linear";
  image.values.reserve(colors.size() * 3);
  for (const color3& color : colors)
    for (int c = 0; c < 3; ++c)
      image.values.push_back(srgb ? linear_to_srgb(std::clamp(color[c], 0.0f, 1.0f)) : color[c]);
  return image;
}

CompareImage film_to_compare_image(const Film& film, bool srgb) {
  std::vector<color3> means;
  means.reserve(film.pixels.size());
  for (const FilmPixel& p : film.pixels) means.push_back(pixel_mean(p));
  return colors_to_compare_image(means, film.width, film.height, srgb);
}

double relative_mse(const CompareImage& image, const CompareImage& reference) {
  double sum = 0;
  for (size_t i = 0; i < image.values.size(); ++i) {
    double a = image.values[i], b = reference.values[i];
    sum += (a - b) * (a - b) / (b * b + 1e-2);
  }
  return image.values.empty() ? 0 : sum / double(image.values.size());
}

std::vector<uint8_t> edge_mask(const CompareImage& reference, double fraction) {
  std::vector<float> gradient(reference.pixel_count());
  for (int y = 0; y < reference.height; ++y)
    for (int x = 0; x < reference.width; ++x) gradient[size_t(y) * reference.width + x] = sobel_magnitude(reference, x, y);
  std::vector<uint8_t> mask(gradient.size(), 0);
  size_t count = std::min(gradient.size(), size_t(std::ceil(fraction * double(gradient.size()))));
  if (count == 0) return mask;
  std::vector<float> sorted = gradient;
  std::nth_element(sorted.begin(), sorted.begin() + (count - 1), sorted.end(), std::greater<float>());
  float cut = sorted[count - 1];
  for (size_t i = 0; i < gradient.size(); ++i) mask[i] = gradient[i] >= cut && gradient[i] > 0;
  return mask;
}

double masked_rmse(const CompareImage& image, const CompareImage& reference, const std::vector<uint8_t>& mask) {
  int channels = image.channels();
  double sum = 0;
  size_t count = 0;
  for (size_t p = 0; p < mask.size(); ++p) {
    if (!mask[p]) continue;
    for (int c = 0; c < channels; ++c) {
      double d = double(image.values[p * channels + c]) - reference.values[p * channels + c];
      sum += d * d;
      ++count;
    }
  }
  return count ? std::sqrt(sum / double(count)) : 0;
}

ErrorMetrics measure_error(const CompareImage& image, const CompareImage& reference, const std::vector<uint8_t>& edges) {
  check_comparable(image, reference);
  CompareMetrics metrics = compute_metrics(image, reference, CompareThresholds{});
  ErrorMetrics error;
  error.rmse = metrics.rmse;
  // From the RMSE with a fixed peak of 1: OpenImageIO's PSNR takes the images' own peak, which
  // moves with the noise and would make steps of a ladder incomparable.
  error.psnr = error.rmse > 0 ? 20 * std::log10(1 / error.rmse) : std::numeric_limits<double>::infinity();
  error.relative_mse = relative_mse(image, reference);
  if (!edges.empty()) error.edge_rmse = masked_rmse(image, reference, edges);
  return error;
}

}  // namespace radiant
