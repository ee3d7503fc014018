#include "film/film_stats.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace radiant {

namespace {

// Pixels per block of the error's sum: fixed, so that the blocks, and so the sum's rounding, do
// not depend on how many threads share them.
constexpr size_t block_pixels = 4096;

}  // namespace

float pixel_relative_error(const FilmPixel& p) {
  if (p.samples < 2) return std::numeric_limits<float>::infinity();
  color3 mean = pixel_mean(p), variance = pixel_mean_variance(p);
  float l = luminance(mean);
  float sigma = std::sqrt(std::max(0.0f, luminance(variance)));
  return sigma / std::max(l, 1e-3f);
}

FilmSampleStats film_sample_stats(const Film& film) {
  FilmSampleStats stats;
  size_t count = film.pixels.size();
  if (count == 0) return stats;
  size_t blocks = (count + block_pixels - 1) / block_pixels;
  struct Block {
    double error_sum = 0;
    size_t error_count = 0;
    uint64_t samples = 0;
    uint32_t min = std::numeric_limits<uint32_t>::max(), max = 0;
  };
  std::vector<Block> partial(blocks);
  tbb::parallel_for(size_t(0), blocks, [&](size_t b) {
    Block& block = partial[b];
    for (size_t i = b * block_pixels, end = std::min(count, i + block_pixels); i < end; ++i) {
      const FilmPixel& p = film.pixels[i];
      block.samples += p.samples;
      block.min = std::min(block.min, p.samples);
      block.max = std::max(block.max, p.samples);
      float e = pixel_relative_error(p);
      if (std::isfinite(e)) block.error_sum += e, ++block.error_count;
    }
  });
  double error_sum = 0;
  size_t error_count = 0;
  stats.min_pixel_samples = std::numeric_limits<uint32_t>::max();
  for (const Block& block : partial) {
    error_sum += block.error_sum, error_count += block.error_count;
    stats.samples += block.samples;
    stats.min_pixel_samples = std::min(stats.min_pixel_samples, block.min);
    stats.max_pixel_samples = std::max(stats.max_pixel_samples, block.max);
  }
  stats.mean_relative_error = error_count ? float(error_sum / double(error_count)) : 0.0f;
  if (stats.min_pixel_samples == stats.max_pixel_samples) {
    // Every pixel took the same samples (any render but an adaptive or interrupted one).
    stats.median_pixel_samples = stats.p90_pixel_samples = stats.min_pixel_samples;
    return stats;
  }
  std::vector<uint32_t> counts(count);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, block_pixels), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t i = range.begin(); i < range.end(); ++i) counts[i] = film.pixels[i].samples;
  });
  auto quantile = [&](double q) {
    auto at = counts.begin() + ptrdiff_t(q * double(count - 1));
    std::nth_element(counts.begin(), at, counts.end());
    return *at;
  };
  stats.median_pixel_samples = quantile(0.5);
  stats.p90_pixel_samples = quantile(0.9);
  return stats;
}

size_t mark_unconverged_pixels(const Film& film, float threshold, std::vector<uint8_t>& unconverged,
                               std::vector<uint8_t>& active) {
  unconverged.assign(film.pixels.size(), 0);
  active.assign(film.pixels.size(), 0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, film.pixels.size(), block_pixels),
                    [&](const tbb::blocked_range<size_t>& range) {
                      for (size_t i = range.begin(); i < range.end(); ++i)
                        unconverged[i] = pixel_relative_error(film.pixels[i]) > threshold;
                    });
  int width = film.width, height = film.height;
  return tbb::parallel_reduce(
      tbb::blocked_range<int>(0, height), size_t(0),
      [&](const tbb::blocked_range<int>& rows, size_t count) {
        for (int y = rows.begin(); y < rows.end(); ++y)
          for (int x = 0; x < width; ++x) {
            bool any = false;
            for (int ny = std::max(0, y - 1); ny <= std::min(height - 1, y + 1) && !any; ++ny)
              for (int nx = std::max(0, x - 1); nx <= std::min(width - 1, x + 1) && !any; ++nx)
                any = unconverged[size_t(ny) * width + nx];
            count += active[size_t(y) * width + x] = any;
          }
        return count;
      },
      std::plus<size_t>());
}

}  // namespace radiant
