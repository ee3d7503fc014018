// Image files for the rest of radiant: PNG read and written directly (libpng), everything else
// through the OpenImageIO module (image_io_module.h), loaded the first time it is needed.
#pragma once

#include <memory>
#include <string>

#include "image/image_io_module.h"
#include "output/temporary_file.h"

namespace radiant {

// The OpenImageIO module, loaded on first use. Throws std::runtime_error when it cannot be
// found or is stale.
const ImageIoModule& image_io_module();

// Opens `path` for reading. Returns null with the reason (one line) in `error`.
std::unique_ptr<ImageSource> open_image_file(const std::string& path, std::string& error);

// The header of the image at `path`, its metadata included (unpacked: packed_metadata.h). Throws
// std::runtime_error "path: why".
ImageHeader read_image_header(const std::string& path);

// Writes `pixels` (spec.channel_names.size() floats per pixel, or 4-byte values of
// spec.channel_types, top row first) to `file` in the format its target's extension names: 8-bit
// PNG directly, any other format through the module (metadata packed when the format is not
// EXR: packed_metadata.h). Values for uint8 are display values in
// [0, 1]. Throws std::runtime_error naming the target.
void write_image_file(TemporaryFile& file, const ImageWriteSpec& spec, const void* pixels);

// The path's extension in lower case, with its dot (".png"), or "".
std::string lowercase_extension(const std::string& path);

}  // namespace radiant
