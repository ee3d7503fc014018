// What the denoiser reads: a linear image with the two half images of its samples (even and odd
// sample indices), the variance of each pixel's mean and the first-hit features, from a film or
// from an EXR that holds them (denoise_channels.h).
#pragma once

#include <cstdint>
#include <vector>

#include "film/film.h"
#include "math/vec.h"

namespace radiant {

// One value per pixel, top row first. `color` is the mean of `even` and `odd` (as the film
// resolves it); `variance` is that of the mean, per channel.
struct DenoiseInput {
  int width = 0, height = 0;
  std::vector<color3> color, even, odd, variance;
  std::vector<vec3> albedo, normal;
  std::vector<float> depth;
};

// The film's image, halves, variance and features. The film must keep AOV sums and halves
// (make_film's with_aovs and with_halves); std::invalid_argument when it does not.
DenoiseInput denoise_input_from_film(const Film& film);

// Bytes a DenoiseInput of `pixels` pixels holds.
constexpr uint64_t denoise_input_pixel_bytes = 6 * sizeof(vec3) + sizeof(float);

}  // namespace radiant
