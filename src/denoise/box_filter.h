// The mean over a (2 radius + 1)^2 square of pixels, the square cut at the image's edges: the
// denoiser smooths its variance estimates, error maps and candidate choices with it.
#pragma once

#include <vector>

#include "math/vec.h"

namespace radiant {

// Runs on the calling task arena's threads; each output pixel sums its inputs in one fixed
// order, so the result is the same for any thread count.
std::vector<float> box_filter(const std::vector<float>& image, int width, int height, int radius);
std::vector<color3> box_filter(const std::vector<color3>& image, int width, int height, int radius);

}  // namespace radiant
