#include "denoise/box_filter.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace radiant {

namespace {

// Rows first, then columns: each a plain sum over the window, not a running one, so that no
// pixel's value depends on where a row starts.
template <class T>
std::vector<T> box_filter_any(const std::vector<T>& image, int width, int height, int radius) {
  std::vector<T> rows(image.size()), out(image.size());
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& range) {
    for (int y = range.begin(); y < range.end(); ++y)
      for (int x = 0; x < width; ++x) {
        int x0 = std::max(0, x - radius), x1 = std::min(width - 1, x + radius);
        T sum{};
        for (int i = x0; i <= x1; ++i) sum += image[size_t(y) * width + i];
        rows[size_t(y) * width + x] = sum / float(x1 - x0 + 1);
      }
  });
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& range) {
    for (int y = range.begin(); y < range.end(); ++y) {
      int y0 = std::max(0, y - radius), y1 = std::min(height - 1, y + radius);
      for (int x = 0; x < width; ++x) {
        T sum{};
        for (int j = y0; j <= y1; ++j) sum += rows[size_t(j) * width + x];
        out[size_t(y) * width + x] = sum / float(y1 - y0 + 1);
      }
    }
  });
  return out;
}

}  // namespace

std::vector<float> box_filter(const std::vector<float>& image, int width, int height, int radius) {
  return box_filter_any(image, width, height, radius);
}

std::vector<color3> box_filter(const std::vector<color3>& image, int width, int height, int radius) {
  return box_filter_any(image, width, height, radius);
}

}  // namespace radiant
