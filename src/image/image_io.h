// Image files for the rest of radiant: PNG read and written directly (libpng), EXR written
// directly (exr_writer.h), everything else through the OpenImageIO module (image_io_module.h),
// loaded the first time it is needed.
#pragma once

#include <memory>
#include <string>

#include "image/image_io_module.h"
#include "memory/memory_budget.h"
#include "output/file_extension.h"
#include "output/temporary_file.h"

namespace radiant {

// The OpenImageIO module, loaded on first use. Throws std::runtime_error when it cannot be
// found or is stale.
const ImageIoModule& image_io_module();

// Opens `path` for reading: every image radiant reads comes through here. Returns null with the
// reason (one line) in `error`, also for anything but a regular file (input_file.h), refused
// before it is opened: a FIFO or a device such as /dev/zero would block or never end. What decoding
// holds is charged to `budget` (if not null) for as long as the source lives: OpenEXR's buffers
// before it opens the file (which allocates them), then the whole image at four bytes a channel
// (OpenImageIO's copy while it converts); the caller charges only its own pixels. Throws
// MemoryLimitError naming `path` when the budget refuses.
std::unique_ptr<ImageSource> open_image_file(const std::string& path, std::string& error, MemoryBudget* budget);

// The header of the image at `path`, its metadata included (unpacked: packed_metadata.h). Throws
// std::runtime_error "path: why" (MemoryLimitError when opening it needs more than `budget` has).
ImageHeader read_image_header(const std::string& path, MemoryBudget* budget);

// Writes `pixels` (spec.channel_names.size() floats per pixel, or 4-byte values of
// spec.channel_types, top row first) to `file` in the format its target's extension names: 8-bit
// PNG and float EXR directly, any other format through the module (metadata packed when the
// format is not EXR: packed_metadata.h). Values for uint8 are display values in [0, 1]. Throws
// std::runtime_error naming the target.
void write_image_file(TemporaryFile& file, const ImageWriteSpec& spec, const void* pixels);


}  // namespace radiant
