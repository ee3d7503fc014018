// OpenEXR output written directly (single-part scanline, ZIP or uncompressed), the format of
// every float render and shard: loading OpenImageIO for it cost about 0.45 s of start-up per
// file, which a script rendering frames or shards pays each time.
#pragma once

#include <string>

#include "image/image_io_module.h"
#include "output/temporary_file.h"

namespace radiant {

// Whether write_exr stores this image: an .exr target whose channels are half or float
// (spec.type), or float and uint32 (spec.channel_types).
bool writes_as_exr(const std::string& path, const ImageWriteSpec& spec);

// Writes `pixels` (spec.channel_names.size() 4-byte values per pixel, top row first: floats, or
// the values of spec.channel_types) to `file` as an OpenEXR file, as OpenImageIO writes it:
// channels sorted by name, the data window at (spec.x, spec.y) inside the display window, ZIP
// (16 scanlines a chunk) when spec.zip, and spec.metadata as string attributes. Half floats are
// rounded to nearest, ties to even, as OpenEXR's own conversion does. One chunk at a time: the
// file is never held in memory. Returns "", or, before writing anything, why the spec cannot be
// stored (duplicate channel names, a metadata name OpenEXR reserves, a name longer than OpenEXR
// allows); failed writes throw as TemporaryFile's do.
std::string write_exr(TemporaryFile& file, const ImageWriteSpec& spec, const void* pixels);

}  // namespace radiant
