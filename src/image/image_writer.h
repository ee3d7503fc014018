// Writing renders: 8-bit sRGB for PNG/JPEG/..., linear float for EXR/HDR.
#pragma once

#include <string>
#include <vector>

#include "image/image_format.h"
#include "image/image_io_module.h"
#include "image/view_transform.h"
#include "memory/memory_budget.h"
#include "output/temporary_file.h"

namespace radiant {

// A float image with named channels ("R", "G", "B", "A" in a transparent render, then AOVs such
// as "albedo.R"). With "A", R, G, B are associated (premultiplied) by it.
struct OutputImage {
  int width = 0, height = 0;
  // Its place in the full image, kept by float formats (EXR data and display windows); a full
  // size of 0 is the image itself.
  int x = 0, y = 0, full_width = 0, full_height = 0;
  std::vector<std::string> channels;
  std::vector<float> pixels;  // interleaved, top row first
  ImageMetadata metadata;     // text attributes recorded in the file (PNG tEXt, EXR header)
  DisplaySettings display;    // exposure and view transform of 8- and 16-bit formats
  int bit_depth = 8;          // 8 or 16, for formats without float storage
  bool half = false;          // float formats: 16-bit half floats instead of 32-bit
};

// True for the formats radiant writes as linear floating point: EXR and HDR (TIFF float is not
// chosen; PFM has no writer in OpenImageIO 2.4).
inline bool is_float_format(const std::string& path) { return image_format_of(path).linear_float; }
// True for the format that holds named channels beyond R, G, B, A and half floats: EXR (HDR's
// RGBE has three channels and one encoding). AOVs, a partial render's sample counts and --half
// need it.
inline bool is_exr_format(const std::string& path) { return image_format_of(path).named_channels; }
// True for the formats radiant writes with an alpha channel (--transparent): PNG, TIFF, EXR.
inline bool stores_alpha(const std::string& path) { return image_format_of(path).alpha; }

// Checks, before any work, that an image can be written to `path`: its extension names a format
// radiant writes (std::invalid_argument, a usage error, when not). Loads now whatever writing it
// will need (the OpenImageIO module for any format but PNG), so that a missing module fails
// before a long render rather than after it (std::runtime_error).
void check_image_output(const std::string& path);

// What writing through OpenImageIO (every format but 8-bit PNG and EXR) costs the process: its
// libraries, their data and its writers' buffers, which stay resident once loaded (measured with
// OpenImageIO 2.4 on Debian 12: 124 MiB more peak memory than a PNG of the same render, whatever
// the image size; the pixels' own buffers are in the render's image charge).
inline constexpr uint64_t image_module_bytes = uint64_t(128) << 20;

// Charges `budget` (when not null) once for OpenImageIO when writing `path` at `bit_depth` needs
// it; throws MemoryLimitError naming `path` when it does not fit.
void charge_image_output(MemoryBudget* budget, const std::string& path, int bit_depth = 8);

// Writes `image` to `file`, which is renamed onto its target when committed. Formats without
// float storage get the color through the exposure and view transform, in 8 or 16 bits, and the
// alpha (when the image has one) straight, unassociated; float formats get every channel as
// linear radiance, the color associated with the alpha. Throws
// std::runtime_error naming the target and the writer's reason.
void write_image(TemporaryFile& file, const OutputImage& image);
// The image as the bytes of an 8-bit sRGB PNG after its exposure and view transform, as
// write_image stores a .png, without metadata: a preview to send elsewhere. Empty, with the
// reason in `error`, on failure.
std::vector<unsigned char> encode_preview_png(const OutputImage& image, std::string& error);

}  // namespace radiant
