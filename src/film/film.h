// The film: per-pixel exact sums of radiance samples and their squares, plus first-hit AOVs and,
// in a transparent render, the coverage (alpha). The sums are ExactSum: any partition of a
// pixel's samples (passes, sample-range shards) summed apart and merged gives the same bits as
// one render.
#pragma once

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "film/exact_sum.h"
#include "math/vec.h"

namespace radiant {

// A pixel filter's samples have weights of one magnitude and either sign (src/sampling/
// pixel_filter.h): the weighted mean sum(w L) / sum(w) of pbrt-v4's film is then
// sum(±L) / (samples - 2 negative_samples), which the pixel keeps exactly without the weights.
struct FilmPixel {
  ExactSum sum[3];          // of the samples, each negated where its weight is negative
  ExactSum sum_squares[3];
  uint32_t samples = 0;
  uint32_t negative_samples = 0;  // samples of negative weight (only Mitchell's lobes make them)
};

// First-hit auxiliary values, summed exactly like the radiance (and in double range: float sums
// of large finite values, an albedo or a depth near 1e38, would overflow to infinity).
struct FilmAovs {
  ExactSum albedo[3];
  ExactSum normal[3];
  ExactSum depth;
};

// The samples of odd index of a pixel, summed apart (weighted as FilmPixel's): with the whole
// pixel they make two independent half images, of the even and of the odd samples, whose
// difference tells the denoiser how much noise and error are left.
struct FilmHalf {
  ExactSum sum[3];
  uint32_t samples = 0;
  uint32_t negative_samples = 0;
};

// The film's allocator: a vector's resize leaves the elements unconstructed, and make_film
// constructs them itself on all of the arena's threads. A 1024² film is a hundred megabytes, and
// constructing it, which also faults in every page, on one thread was the longest serial step
// left before a render. Only make_film resizes a film; copies construct as usual.
template <class T>
struct FilmAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = FilmAllocator<U>;
  };
  FilmAllocator() = default;
  template <class U>
  FilmAllocator(const FilmAllocator<U>&) noexcept {}
  template <class U>
  void construct(U*) noexcept {}  // value-initialization: make_film's
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};
template <class T>
using FilmVector = std::vector<T, FilmAllocator<T>>;

struct Film {
  int width = 0, height = 0;
  // Where the film lies in the full image: a cropped render or a shard is a window of it.
  int x = 0, y = 0, full_width = 0, full_height = 0;
  FilmVector<FilmPixel> pixels;
  FilmVector<FilmAovs> aovs;  // one per pixel when the render keeps AOVs, else empty
  // The sum of each sample's coverage (1 where the camera ray met geometry, 0 where it saw the
  // background), one per pixel in a transparent render, else empty.
  FilmVector<ExactSum> alpha;
  FilmVector<FilmHalf> odd_half;  // one per pixel when the render keeps half images, else empty
  FilmPixel& at(int x, int y) { return pixels[size_t(y) * width + x]; }
  const FilmPixel& at(int x, int y) const { return pixels[size_t(y) * width + x]; }
};

// A film of black pixels without samples, the whole image; `with_aovs` also makes the AOV sums,
// `with_alpha` the coverage sums, `with_halves` the odd samples' sums. Constructed on the calling
// task arena's threads.
Film make_film(int width, int height, bool with_aovs = false, bool with_alpha = false, bool with_halves = false);

// Adds a sample; `negative`: its filter weight is negative.
inline void add_sample(FilmPixel& p, color3 radiance, bool negative = false) {
  color3 value = negative ? -radiance : radiance;
  for (int c = 0; c < 3; ++c) {
    p.sum[c].add(value[c]);
    p.sum_squares[c].add(double(value[c]) * value[c]);  // exact: a float's square fits a double
  }
  p.samples++;
  p.negative_samples += negative;
}

// Adds a sample of odd index to its pixel's half (after add_sample added it to the pixel).
inline void add_half_sample(FilmHalf& half, color3 radiance, bool negative = false) {
  color3 value = negative ? -radiance : radiance;
  for (int c = 0; c < 3; ++c) half.sum[c].add(value[c]);
  half.samples++;
  half.negative_samples += negative;
}

// The sum of a pixel's weights over their magnitude: its samples less twice the negative ones.
inline double pixel_weight(const FilmPixel& p) { return double(p.samples) - 2.0 * double(p.negative_samples); }

// Adds every sample of `from` to `to` (merging shards of the same pixel).
void add_pixel(FilmPixel& to, const FilmPixel& from);
void add_aovs(FilmAovs& to, const FilmAovs& from);
void add_half(FilmHalf& to, const FilmHalf& from);

// Weighted means of a pixel's even- and odd-indexed samples; a half without samples (or whose
// weights cancel) takes the whole pixel's mean.
void pixel_half_means(const FilmPixel& p, const FilmHalf& odd, color3& even_mean, color3& odd_mean);

// Weighted mean radiance of a pixel (black without samples, or when its weights cancel).
color3 pixel_mean(const FilmPixel& p);
// Variance of the pixel mean (sample variance / samples, over the mean weight squared when a
// filter weighs the samples), per channel. It saturates at the largest float, which only pixels
// whose mean exceeds ~1.8e19 (or whose weights cancel) reach: the value written is always
// finite, and a smaller variance only makes a comparison stricter.
color3 pixel_mean_variance(const FilmPixel& p);

// A pixel's first-hit features as images show them: the albedo and depth averaged over its
// samples, the normal summed and normalised (0 where nothing was hit).
color3 pixel_albedo(const FilmPixel& p, const FilmAovs& a);
vec3 pixel_normal(const FilmAovs& a);
float pixel_depth(const FilmPixel& p, const FilmAovs& a);

// Weighted mean coverage of pixel `i` of a transparent film (0 as pixel_mean).
float pixel_alpha(const Film& film, size_t i);

// Bytes a film of one pixel takes, with or without AOVs, coverage and halves (for the memory
// budget).
constexpr uint64_t film_pixel_bytes(bool with_aovs, bool with_alpha = false, bool with_halves = false) {
  return sizeof(FilmPixel) + (with_aovs ? sizeof(FilmAovs) : 0) + (with_alpha ? sizeof(ExactSum) : 0) +
         (with_halves ? sizeof(FilmHalf) : 0);
}

}  // namespace radiant
