// The film: per-pixel exact sums of radiance samples and their squares, plus first-hit AOVs.
// The sums are ExactSum: any partition of a pixel's samples (passes, sample-range shards) summed
// apart and merged gives the same bits as one render.
#pragma once

#include <cstdint>
#include <vector>

#include "film/exact_sum.h"
#include "math/vec.h"

namespace radiant {

struct FilmPixel {
  ExactSum sum[3];
  ExactSum sum_squares[3];
  uint32_t samples = 0;
};

// First-hit auxiliary values, summed exactly like the radiance (and in double range: float sums
// of large finite values, an albedo or a depth near 1e38, would overflow to infinity).
struct FilmAovs {
  ExactSum albedo[3];
  ExactSum normal[3];
  ExactSum depth;
};

struct Film {
  int width = 0, height = 0;
  // Where the film lies in the full image: a cropped render or a shard is a window of it.
  int x = 0, y = 0, full_width = 0, full_height = 0;
  std::vector<FilmPixel> pixels;
  std::vector<FilmAovs> aovs;  // one per pixel when the render keeps AOVs, else empty
  FilmPixel& at(int x, int y) { return pixels[size_t(y) * width + x]; }
  const FilmPixel& at(int x, int y) const { return pixels[size_t(y) * width + x]; }
};

// A film of black pixels without samples, the whole image; `with_aovs` also makes the AOV sums.
Film make_film(int width, int height, bool with_aovs = false);

inline void add_sample(FilmPixel& p, color3 radiance) {
  for (int c = 0; c < 3; ++c) {
    p.sum[c].add(radiance[c]);
    p.sum_squares[c].add(double(radiance[c]) * radiance[c]);  // exact: a float's square fits a double
  }
  p.samples++;
}

// Adds every sample of `from` to `to` (merging shards of the same pixel).
void add_pixel(FilmPixel& to, const FilmPixel& from);
void add_aovs(FilmAovs& to, const FilmAovs& from);

// Mean radiance of a pixel (black without samples).
color3 pixel_mean(const FilmPixel& p);
// Variance of the pixel mean (sample variance / samples), per channel. It saturates at the
// largest float, which only pixels whose mean exceeds ~1.8e19 reach: the value written is
// always finite, and a smaller variance only makes a comparison stricter.
color3 pixel_mean_variance(const FilmPixel& p);

// Bytes a film of one pixel takes, with or without AOVs (for the memory budget).
constexpr uint64_t film_pixel_bytes(bool with_aovs) {
  return sizeof(FilmPixel) + (with_aovs ? sizeof(FilmAovs) : 0);
}

}  // namespace radiant
