// Writing renders: 8-bit sRGB for PNG/JPEG/..., linear float for EXR/HDR.
#pragma once

#include <string>
#include <vector>

namespace radiant {

// A float image with named channels ("R", "G", "B", then AOVs such as "albedo.R").
struct OutputImage {
  int width = 0, height = 0;
  std::vector<std::string> channels;
  std::vector<float> pixels;  // interleaved, top row first
};

// True for formats that store linear floating point (EXR, HDR, PFM, TIFF float is not chosen).
bool is_float_format(const std::string& path);

// Writes atomically: a temporary file beside `path`, then a rename, so an existing file is never
// left half-written. Formats without float storage get the first three channels, sRGB-encoded
// and clamped to 8 bits. Throws std::runtime_error with the writer's reason.
void write_image(const std::string& path, const OutputImage& image);

// A hidden file in the same folder with the same extension, unique to this process: written
// first and renamed onto `path`, so that the rename is atomic and the extension names the format.
std::string temporary_path_beside(const std::string& path);

// Loads now whatever writing `path` will need (the OpenImageIO module for any format but PNG),
// so that a missing module fails before a long render rather than after it. Throws
// std::runtime_error.
void prepare_image_writer(const std::string& path);

// Linear to sRGB transfer function (IEC 61966-2-1), for values in [0, 1].
float linear_to_srgb(float linear);

}  // namespace radiant
