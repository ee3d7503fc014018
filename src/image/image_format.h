// What radiant knows about each output image format, by its extension: one table that the
// writers, the flag checks and `radiant info` read instead of comparing extensions.
#pragma once

#include <string>

#include "output/file_extension.h"

namespace radiant {

// Who writes a format: radiant's own PNG or EXR writer, or the OpenImageIO module.
enum class ImageWriterKind { png, exr, module };

struct ImageFormat {
  const char* extension;  // lower case, with its dot
  ImageWriterKind writer;
  bool linear_float;      // every channel stored as linear float; else display-encoded 8 or 16 bits
  bool alpha;             // holds the alpha of --transparent
  bool sixteen_bit;       // --bit-depth 16
  bool named_channels;    // channels beyond R, G, B, A (AOVs, sample counts), half floats, shards
  bool header_metadata;   // keeps every metadata attribute in its header; else packed into a description
  bool radiance_header;   // Radiance RGBE: the metadata also goes into its header lines
};

inline constexpr ImageFormat image_formats[] = {
    // extension writer                  float  alpha  16-bit named  header radiance
    {".png", ImageWriterKind::png, false, true, true, false, false, false},
    {".exr", ImageWriterKind::exr, true, true, false, true, true, false},
    {".hdr", ImageWriterKind::module, true, false, false, false, false, true},
    {".tif", ImageWriterKind::module, false, true, true, false, false, false},
    {".tiff", ImageWriterKind::module, false, true, true, false, false, false},
    {".jpg", ImageWriterKind::module, false, false, false, false, false, false},
    {".jpeg", ImageWriterKind::module, false, false, false, false, false, false},
    {".pfm", ImageWriterKind::module, false, false, false, false, false, false},
    {".bmp", ImageWriterKind::module, false, false, false, false, false, false},
    {".tga", ImageWriterKind::module, false, false, false, false, false, false},
    {".webp", ImageWriterKind::module, false, false, false, false, false, false},
    {".ppm", ImageWriterKind::module, false, false, false, false, false, false},
    {".pgm", ImageWriterKind::module, false, false, false, false, false, false},
    {".dpx", ImageWriterKind::module, false, false, false, false, false, false},
};

// Any other extension: whatever OpenImageIO makes of it, 8-bit without alpha.
inline constexpr ImageFormat other_image_format = {"", ImageWriterKind::module, false, false, false, false, false, false};

// The format `path`'s extension names, or other_image_format when the table does not list it.
inline const ImageFormat& image_format_of(const std::string& path) {
  std::string extension = lowercase_extension(path);
  for (const ImageFormat& format : image_formats)
    if (extension == format.extension) return format;
  return other_image_format;
}

// Whether the table lists `path`'s extension.
inline bool is_known_image_extension(const std::string& path) { return image_format_of(path).extension[0] != 0; }

}  // namespace radiant
