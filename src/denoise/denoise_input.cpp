#include "denoise/denoise_input.h"

#include <tbb/parallel_for.h>

#include <stdexcept>

namespace radiant {

DenoiseInput denoise_input_from_film(const Film& film) {
  size_t count = film.pixels.size();
  if (film.aovs.size() != count || film.odd_half.size() != count)
    throw std::invalid_argument("the denoiser needs a film with AOV sums and half images");
  DenoiseInput in;
  in.width = film.width, in.height = film.height;
  in.color.resize(count), in.even.resize(count), in.odd.resize(count), in.variance.resize(count);
  in.albedo.resize(count), in.normal.resize(count), in.depth.resize(count);
  tbb::parallel_for(size_t(0), count, [&](size_t i) {
    const FilmPixel& p = film.pixels[i];
    const FilmAovs& a = film.aovs[i];
    in.color[i] = pixel_mean(p);
    pixel_half_means(p, film.odd_half[i], in.even[i], in.odd[i]);
    in.variance[i] = pixel_mean_variance(p);
    in.albedo[i] = pixel_albedo(p, a);
    in.normal[i] = pixel_normal(a);
    in.depth[i] = pixel_depth(p, a);
  });
  return in;
}

}  // namespace radiant
