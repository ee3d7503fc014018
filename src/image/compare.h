// Image comparison for regression tests: plain error metrics with thresholds (built on
// OpenImageIO's ImageBufAlgo::compare) and a Monte-Carlo-aware per-pixel z-test.
// docs/compare.md explains every metric and when to use which mode.
#pragma once

#include <cmath>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "memory/memory_budget.h"

namespace radiant {

// An image that cannot be compared (unreadable, mismatched sizes or channels). what() is one
// line naming the file.
struct CompareError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// -----------------------------------------------------------------------------------------------
// Images as compared
// -----------------------------------------------------------------------------------------------

// The channels of one image that take part in a comparison, as float, in the file's own
// encoding (8-bit PNG reads as sRGB-encoded [0,1], EXR as linear).
// Where an image's pixels lie (EXR's data window) and what a viewer shows (its display window).
struct ImageWindow {
  int x = 0, y = 0, width = 0, height = 0;
  bool operator==(const ImageWindow&) const = default;
};

struct CompareImage {
  std::string path;
  int width = 0, height = 0;
  // As the file says; a window of width 0 (an image made in memory) is {0, 0, width, height}.
  ImageWindow data_window, display_window;
  std::vector<std::string> channel_names;  // the compared channels: R,G,B[,A] or the first ones
  std::vector<float> values;               // width*height*channel_names.size(), row-major
  std::vector<float> variance;  // variance of each value's mean estimate, same layout; or empty
  std::string color_space;      // OIIO's "oiio:ColorSpace", e.g. "sRGB" or "Linear"; may be empty
  bool has_alpha = false;       // the last compared channel is alpha (it has no variance)
  // The budget's charge for values and variance read from a file, given back when the last copy
  // goes (a copy is its maker's own allocation).
  std::shared_ptr<MemoryCharge> memory;
  int channels() const { return int(channel_names.size()); }
  int color_channels() const { return channels() - (has_alpha ? 1 : 0); }
  size_t pixel_count() const { return size_t(width) * height; }
};

// Reads `path` with OpenImageIO: only an image stored as a viewer shows it (Orientation 1, one
// part or page: else CompareError), its color channels (R,G,B by name, else the first three, else
// all of a one- or two-channel image), its alpha when present, and its variance AOV (channels
// variance.R, variance.G, variance.B) when it has one. Throws CompareError, or MemoryLimitError
// when reading it needs more than `budget` (if not null) has left.
CompareImage read_compare_image(const std::string& path, MemoryBudget* budget);

// Alpha takes part only when both images have it: drops it from the one that has it otherwise.
void match_alpha(CompareImage& a, CompareImage& b);

// Reads a variance image for `image` from `path`, dividing by `samples_per_pixel` because the
// file holds per-sample variance: its variance.R/G/B channels, else its color channels, else its
// single channel for every color channel. Throws CompareError on a size mismatch, or
// MemoryLimitError as read_compare_image; the budget is charged only while it reads.
std::vector<float> read_variance_image(const std::string& path, const CompareImage& image,
                                       int samples_per_pixel, MemoryBudget* budget);

// Throws CompareError unless `a` and `b` have the same size and number of compared channels, and
// the same data and display windows (pixels that lie elsewhere are not the same picture).
void check_comparable(const CompareImage& a, const CompareImage& b);

// Equal numbers, equal infinities, or NaN facing NaN: values that do not differ.
inline bool same_value(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

// A NaN or infinity facing a different value: a difference no threshold or noise explains.
inline bool nonfinite_difference(double a, double b) {
  return !same_value(a, b) && (!std::isfinite(a) || !std::isfinite(b));
}

// The first non-finite statistic that fails a comparison whatever its thresholds, for the
// message: a NaN or infinity facing a different value ("b.exr: R at (7, 0) is nan where a.exr
// has 0.5"), else a NaN or infinite variance ("a.exr: variance.R at (0, 0) is inf"); "" if none.
std::string first_nonfinite(const CompareImage& a, const CompareImage& b);

// -----------------------------------------------------------------------------------------------
// Plain metrics and thresholds
// -----------------------------------------------------------------------------------------------

enum class Verdict { pass, warn, fail };
const char* verdict_name(Verdict verdict);

// Thresholds in the spirit of OIIO's idiff; the defaults fail a whole image 5% brighter and
// pass 8-bit rounding or float noise (docs/compare.md).
struct CompareThresholds {
  double fail = 0.02;            // a pixel fails when any channel differs by more
  double fail_percent = 1.0;     // the test fails when more than this % of pixels fail
  double warn = 0.004;           // a pixel warns when any channel differs by more (~1/255)
  double warn_percent = 10.0;    // the test warns when more than this % of pixels warn
  double fail_relative = 0.02;   // the test fails when mean_relative_error exceeds this
  double warn_relative = 0.005;  // the test warns when mean_relative_error exceeds this
};

// Metrics over every compared value (pixel × channel).
struct CompareMetrics {
  size_t pixels = 0;
  int channels = 0;
  double rmse = 0;                 // root mean squared error
  double psnr = 0;                 // 20·log10(1 / rmse), +inf when identical (peak value 1)
  double max_error = 0;            // largest absolute difference
  int max_x = 0, max_y = 0, max_channel = 0;  // where it is
  double mean_error = 0;           // mean absolute difference
  double mean_relative_error = 0;  // Σ|a−b| / Σ(|a|+|b|)/2: error relative to the mean level
  size_t fail_pixels = 0;          // pixels with a channel differing by more than `fail`
  size_t warn_pixels = 0;          // pixels with a channel differing by more than `warn`
  double fail_fraction = 0;        // fail_pixels / pixels
  double warn_fraction = 0;        // warn_pixels / pixels
  size_t nonfinite_pixels = 0;     // pixels with a nonfinite_difference: fail the test outright
};

// The metrics of `a` against `b` (same size and channel count; see check_comparable).
CompareMetrics compute_metrics(const CompareImage& a, const CompareImage& b,
                               const CompareThresholds& thresholds);

// Fail when a pixel has a nonfinite_difference; fail or warn when the pixel fractions or the
// mean relative error exceed the thresholds.
Verdict threshold_verdict(const CompareMetrics& metrics, const CompareThresholds& thresholds);

// -----------------------------------------------------------------------------------------------
// Monte Carlo z-test
// -----------------------------------------------------------------------------------------------

// Per value z = (a−b) / sqrt(var_a + var_b + (epsilon·(1 + (|a|+|b|)/2))²), two-sided p-value,
// tested against the Šidák-corrected level for all values at once (as Mitsuba 3's render tests).
struct ZTestParams {
  double alpha = 0.01;                 // chance that two renders of the same mean fail
  double allowed_fail_percent = 0.25;  // % of pixels that may fail (fireflies), as Mitsuba
  double epsilon = 5e-4;               // relative floor of the deviation: roundoff, half floats
  // The largest standard deviation a value's mean estimate may claim, as a multiple of
  // 1 + |value|: a larger variance excuses any difference, so it fails the test (docs/compare.md).
  double max_relative_deviation = 4;
  // Also fail when Σz/√N (a whole-image bias, which the per-value test misses under heavy noise)
  // is significant at alpha; sound only when pixels are independent (no wide pixel filter).
  bool bias_test = false;
};

struct ZTestResult {
  size_t tests = 0;             // values tested: pixels × channels
  double alpha_corrected = 0;   // per-test level: sidak_level(alpha, tests)
  double z_critical = 0;        // |z| above which a value fails
  double max_abs_z = 0;         // largest |z|
  double min_p_value = 1;       // smallest two-sided p-value
  size_t fail_pixels = 0;       // pixels with a channel whose p-value is below alpha_corrected
  double fail_fraction = 0;     // fail_pixels / pixels
  double bias_z = 0;            // Σz/√N over the finite z: standard normal for equal means
  double bias_p_value = 1;      // its two-sided p-value
  // Values no z can be computed for: a NaN or infinite variance (which would pass any
  // difference as noise) or a nonfinite_difference. Any of them fails the test.
  size_t nonfinite_values = 0;
  // Values whose variance is finite but beyond plausible_variance: any of them fails the test.
  size_t implausible_values = 0;
  std::vector<float> abs_z;     // per pixel, the largest |z| over its channels
  Verdict verdict = Verdict::pass;
};

// The per-test significance level keeping the family-wise error rate at `alpha` over `tests`
// independent tests: 1 − (1 − alpha)^(1/tests).
double sidak_level(double alpha, size_t tests);

// The |z| whose two-sided p-value is `p`.
double two_sided_critical_z(double p);

// Whether `variance` is one the mean estimate `value` can have: its standard deviation at most
// max_relative_deviation · (1 + |value|). A mean of non-negative samples never has a standard
// deviation above the mean itself (one sample carrying the whole pixel is the extreme); the
// factor leaves room for the Mitchell filter's negative lobes and the 1 for dark pixels.
inline bool plausible_variance(double value, double variance, double max_relative_deviation) {
  double deviation = max_relative_deviation * (1 + std::abs(value));
  return !(variance > deviation * deviation);
}

// The first finite variance that is not plausible_variance, for the message ("a.exr:
// variance.R at (0, 0) is 3e+38, a deviation no mean of 0.9 has (the bound is 7.6)"); "" if none.
std::string first_implausible_variance(const CompareImage& a, const CompareImage& b, double max_relative_deviation);

// Needs a variance in at least one of `a` and `b`; a missing one counts as zero.
ZTestResult run_z_test(const CompareImage& a, const CompareImage& b, const ZTestParams& params);

// Per pixel, the largest absolute difference over the channels (the input of a --diff image).
std::vector<float> pixel_max_difference(const CompareImage& a, const CompareImage& b);

}  // namespace radiant
