// PNG input through libpng with radiant's own error and warning handlers. OpenImageIO's PNG reader
// leaves libpng's defaults, which print "libpng error: ..." on stderr beside radiant's one-line
// message; and a PNG then needs no OpenImageIO at all, like the PNG writer.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "image/image_io_module.h"

namespace radiant {

// The largest metadata chunk (text, ICC profile, ...) a PNG may hold: the largest allocation
// its header can ask libpng for.
constexpr size_t max_png_metadata_chunk_bytes = size_t(8) << 20;

// Whether the file at `path` starts with the PNG signature.
bool is_png_file(const std::string& path);

// Opens a PNG as OpenImageIO presents one: palette and bit depths under 8 expanded, transparency
// as an alpha channel, channels R,G,B[,A] or Y[,A], 8 or 16 bits scaled to [0, 1]. Alpha is read
// as stored (unassociated). Returns null with the reason (one line) in `error`.
std::unique_ptr<ImageSource> open_png(const std::string& path, std::string& error);

}  // namespace radiant
