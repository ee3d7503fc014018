// Image metadata in formats that keep only the text fields they define. EXR keeps any attribute
// and radiant's own PNG writer any text chunk, but TIFF keeps only its tags, and OpenImageIO's
// PNG and JPEG writers drop names such as "radiant:spp": there every attribute travels as one
// line of a single description (TIFF's ImageDescription, PNG's Description), and comes back out.
#pragma once

#include "image/image_io_module.h"

namespace radiant {

// "Software" as it is, and every attribute (Software included) as a line "NAME: VALUE" of an
// ImageDescription whose first line marks it as radiant's; newlines and backslashes in values
// are escaped (\n, \\).
ImageMetadata packed_metadata(const ImageMetadata& metadata);

// `text` on one line: newlines and backslashes escaped as \n and \\.
std::string escaped_metadata_value(const std::string& text);

// `metadata` with a description packed_metadata made replaced by the attributes it holds.
// Anything else, a foreign description included, is kept as it is.
ImageMetadata unpacked_metadata(const ImageMetadata& metadata);

}  // namespace radiant
