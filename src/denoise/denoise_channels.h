// The denoiser's input as named image channels: what `radiant denoise` reads from an EXR (one
// rendered with --aov albedo,normal,depth,halves, or merged from such shards), and the denoised
// colour written back into an image.
#pragma once

#include <string>
#include <vector>

#include "denoise/denoise_input.h"
#include "image/image_writer.h"

namespace radiant {

// The channels the denoiser needs, in the names film_to_image gives them.
const std::vector<std::string>& denoise_channel_names();

// The input from an image of `width` x `height` pixels whose interleaved float `pixels` have the
// channels `channels` (variance.R, G, B when present; else the variance is estimated from the
// halves). Throws std::runtime_error "`path`: ..." naming the first channel missing, or the first
// pixel and channel that is not finite.
DenoiseInput denoise_input_from_channels(int width, int height, const std::vector<std::string>& channels,
                                         const std::vector<float>& pixels, const std::string& path);

// Puts `color` (one per pixel) into channels R, G, B of `image`.
void set_image_color(OutputImage& image, const std::vector<color3>& color);

}  // namespace radiant
