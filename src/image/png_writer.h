// 8-bit PNG output, the format of most renders, written by radiant itself with zlib: without
// OpenImageIO, so that a render never loads its libraries, and compressed on all threads.
#pragma once

#include <string>
#include <vector>

#include "image/image_io_module.h"

namespace radiant {

// Whether encode_png stores this image: 8 bits, gray, RGB or RGBA.
bool writes_as_png(const std::string& path, const ImageWriteSpec& spec);

// `pixels` (1, 3 or 4 channels of display values in [0, 1], clamped and rounded to 8 bits as
// OpenImageIO does; a fourth is straight alpha, as PNG stores it) as the bytes of an sRGB PNG
// file, with spec.metadata as text chunks (tEXt, or iTXt for UTF-8 beyond ASCII) in the order
// given. Empty, with the reason in `error`, on failure.
std::vector<unsigned char> encode_png(const ImageWriteSpec& spec, const float* pixels, std::string& error);

}  // namespace radiant
