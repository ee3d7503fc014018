// What a render reports of its film: how many samples its pixels took, how noisy they still are,
// and, between passes of adaptive sampling, which pixels need more. Each is a pass over every
// pixel, run on the calling task arena's threads: at 1024² a serial pass was a visible part of a
// preview's wall time.
#pragma once

#include <cstdint>
#include <vector>

#include "film/film.h"

namespace radiant {

// Relative standard error of a pixel's mean luminance (0 for black, converged pixels; infinite
// below two samples).
float pixel_relative_error(const FilmPixel& p);

struct FilmSampleStats {
  uint64_t samples = 0;
  uint32_t min_pixel_samples = 0, median_pixel_samples = 0, p90_pixel_samples = 0, max_pixel_samples = 0;
  float mean_relative_error = 0;  // over the pixels whose error is finite
};

// The same numbers for any thread count: the error is summed in fixed blocks of pixels, and the
// blocks' sums are added in order.
FilmSampleStats film_sample_stats(const Film& film);

// Sets active[i] to whether pixel i or one of its eight neighbours has a relative error above
// `threshold` (both vectors are resized to the film; `unconverged` keeps the pixels' own verdict);
// returns how many are active. The neighbourhood makes the estimate robust where a pixel's own
// samples all agree by chance (every one missed the light, so its variance reads zero) while the
// pixels around it are still noisy, as Cycles dilates its mask.
size_t mark_unconverged_pixels(const Film& film, float threshold, std::vector<uint8_t>& unconverged,
                               std::vector<uint8_t>& active);

}  // namespace radiant
