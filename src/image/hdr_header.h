// Radiance HDR files keep no attributes, but their header may hold any text line (Radiance's own
// tools record their command lines there). radiant writes its metadata there, one line each.
#pragma once

#include "image/image_io_module.h"
#include "output/temporary_file.h"

namespace radiant {

// Inserts "NAME=VALUE" (the value escaped as packed_metadata does) for every attribute after the
// first line ("#?RADIANCE") of the HDR file just written to `file`: "radiant:partial=interrupted
// by SIGTERM". Readers (OpenImageIO, Radiance's getinfo) skip or show lines they do not know.
void add_hdr_header_lines(TemporaryFile& file, const ImageMetadata& metadata);

}  // namespace radiant
