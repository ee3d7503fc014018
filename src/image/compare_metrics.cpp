// Plain error metrics: OpenImageIO's compare for RMSE, PSNR, max/mean error and the counts over
// thresholds; here only what it lacks (the mean relative error, fractions, the verdict).
#include <cmath>
#include <limits>
#include <sstream>

#include "image/compare.h"
#include "image/image_io.h"

namespace radiant {

namespace {

// Σ|a−b| / Σ(|a|+|b|)/2 over finite pairs: black pixels do not dilute it, and a uniform scale by
// s reads |s−1|/((1+s)/2) whatever the image shows.
double mean_relative_error(const CompareImage& a, const CompareImage& b) {
  double error = 0, level = 0;
  for (size_t i = 0; i < a.values.size(); ++i) {
    double x = a.values[i], y = b.values[i];
    if (!std::isfinite(x) || !std::isfinite(y)) continue;  // OIIO's counts already fail them
    error += std::abs(x - y);
    level += (std::abs(x) + std::abs(y)) / 2;
  }
  return level > 0 ? error / level : 0;
}

// Pixels OIIO's counts miss: a NaN facing a non-NaN makes |a−b| NaN, which is over no threshold.
size_t nan_only_pixels(const CompareImage& a, const CompareImage& b, double threshold) {
  int channels = a.channels();
  size_t count = 0;
  for (size_t p = 0; p < a.pixel_count(); ++p) {
    bool nan_mismatch = false, over = false;
    for (int c = 0; c < channels; ++c) {
      float x = a.values[p * channels + c], y = b.values[p * channels + c];
      nan_mismatch = nan_mismatch || std::isnan(x) != std::isnan(y);
      over = over || std::abs(x - y) > threshold;
    }
    count += nan_mismatch && !over ? 1 : 0;
  }
  return count;
}

size_t nonfinite_pixels(const CompareImage& a, const CompareImage& b) {
  int channels = a.channels();
  size_t count = 0;
  for (size_t p = 0; p < a.pixel_count(); ++p) {
    bool differs = false;
    for (int c = 0; c < channels; ++c)
      differs = differs || nonfinite_difference(a.values[p * channels + c], b.values[p * channels + c]);
    count += differs ? 1 : 0;
  }
  return count;
}

// "nan", "inf", "-inf" or the number as the table prints it.
std::string value_text(float value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// "R at (7, 0)": channel `c` of value `i` of `image`, named for messages.
std::string place_of(const CompareImage& image, size_t i, const std::string& prefix = "") {
  size_t p = i / size_t(image.channels());
  return prefix + image.channel_names[i % size_t(image.channels())] + " at (" +
         std::to_string(p % size_t(image.width)) + ", " + std::to_string(p / size_t(image.width)) + ")";
}

}  // namespace

std::string first_nonfinite(const CompareImage& a, const CompareImage& b) {
  for (size_t i = 0; i < a.values.size(); ++i)
    if (nonfinite_difference(a.values[i], b.values[i])) {
      const CompareImage& odd = std::isfinite(a.values[i]) ? b : a;
      const CompareImage& other = &odd == &a ? b : a;
      return odd.path + ": " + place_of(odd, i) + " is " + value_text(odd.values[i]) + " where " +
             other.path + " has " + value_text(other.values[i]);
    }
  for (const CompareImage* image : {&a, &b})
    for (size_t i = 0; i < image->variance.size(); ++i)
      if (!std::isfinite(image->variance[i]))
        return image->path + ": " + place_of(*image, i, "variance.") + " is " + value_text(image->variance[i]);
  return "";
}

std::string first_implausible_variance(const CompareImage& a, const CompareImage& b, double max_relative_deviation) {
  for (const CompareImage* image : {&a, &b})
    for (size_t i = 0; i < image->variance.size(); ++i) {
      double value = image->values[i], variance = image->variance[i];
      if (std::isfinite(variance) && !plausible_variance(value, variance, max_relative_deviation))
        return image->path + ": " + place_of(*image, i, "variance.") + " is " + value_text(variance) +
               ", a deviation no mean of " + value_text(value) + " has (the bound is " +
               value_text(max_relative_deviation * (1 + std::abs(value))) + ")";
    }
  return "";
}

const char* verdict_name(Verdict verdict) {
  switch (verdict) {
    case Verdict::pass: return "pass";
    case Verdict::warn: return "warn";
    case Verdict::fail: return "fail";
  }
  return "fail";
}

CompareMetrics compute_metrics(const CompareImage& a, const CompareImage& b,
                               const CompareThresholds& thresholds) {
  PixelDifference result = image_io_module().compare(a.values.data(), b.values.data(), a.width, a.height,
                                                     a.channels(), float(thresholds.fail), float(thresholds.warn));
  if (!result.error.empty()) throw CompareError("cannot compare " + a.path + " and " + b.path + ": " + result.error);
  CompareMetrics metrics;
  metrics.pixels = a.pixel_count();
  metrics.channels = a.channels();
  metrics.rmse = result.rms_error;
  metrics.psnr = result.rms_error > 0 ? result.psnr : std::numeric_limits<double>::infinity();
  metrics.max_error = result.max_error;
  metrics.max_x = result.max_x;
  metrics.max_y = result.max_y;
  metrics.max_channel = result.max_channel;
  metrics.mean_error = result.mean_error;
  metrics.mean_relative_error = mean_relative_error(a, b);
  metrics.fail_pixels = result.fail_pixels + nan_only_pixels(a, b, thresholds.fail);
  metrics.warn_pixels = result.warn_pixels + nan_only_pixels(a, b, thresholds.warn);
  metrics.fail_fraction = double(metrics.fail_pixels) / double(metrics.pixels);
  metrics.warn_fraction = double(metrics.warn_pixels) / double(metrics.pixels);
  metrics.nonfinite_pixels = nonfinite_pixels(a, b);
  return metrics;
}

Verdict threshold_verdict(const CompareMetrics& metrics, const CompareThresholds& thresholds) {
  if (metrics.nonfinite_pixels > 0 || metrics.fail_fraction * 100 > thresholds.fail_percent ||
      metrics.mean_relative_error > thresholds.fail_relative)
    return Verdict::fail;
  if (metrics.warn_fraction * 100 > thresholds.warn_percent ||
      metrics.mean_relative_error > thresholds.warn_relative)
    return Verdict::warn;
  return Verdict::pass;
}

std::vector<float> pixel_max_difference(const CompareImage& a, const CompareImage& b) {
  int channels = a.channels();
  std::vector<float> difference(a.pixel_count(), 0.0f);
  for (size_t p = 0; p < difference.size(); ++p)
    for (int c = 0; c < channels; ++c) {
      float x = a.values[p * channels + c], y = b.values[p * channels + c];
      float d = same_value(x, y) ? 0.0f : std::abs(x - y);
      difference[p] = std::isnan(d) ? std::numeric_limits<float>::infinity()
                                    : std::max(difference[p], d);
    }
  return difference;
}

}  // namespace radiant
