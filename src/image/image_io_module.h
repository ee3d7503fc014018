// The interface of radiant's OpenImageIO module (modules/oiio/): reading images, writing every
// format OpenImageIO knows, and its pixel comparison. radiant loads the module only when a file
// needs it (src/image/image_io.h): OpenImageIO brings about 265 shared libraries whose linking
// takes a quarter of a second at every start, and a render to PNG needs none of them.
// Core and module are built together by the same compiler, so C++ types may cross.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace radiant {

// uint32 stores exact integers (a shard's accumulators); `other` is a type read from a file that
// radiant never writes; uint16 is a 16-bit display image (--bit-depth 16).
enum class PixelType { uint8, half, float32, uint32, other, uint16 };

// A file's text attributes as name and value: PNG tEXt chunks, EXR string header attributes.
using ImageMetadata = std::vector<std::pair<std::string, std::string>>;

// What a file says about subimage 0.
struct ImageHeader {
  int width = 0, height = 0, depth = 1, channels = 0;
  // The data window's origin and the display window (the full image) it lies in: a cropped
  // render or a shard is a window of a larger image.
  int x = 0, y = 0, full_x = 0, full_y = 0, full_width = 0, full_height = 0;
  std::vector<PixelType> channel_types;  // as stored
  int alpha_channel = -1;  // as the file marks it, or -1
  bool deep = false;
  std::vector<std::string> channel_names;
  std::string color_space;  // OpenImageIO's "oiio:ColorSpace": "sRGB", "Linear", ... or empty
  ImageMetadata metadata;   // every string attribute
  // The TIFF/Exif Orientation: 1 is stored as shown; 2 to 8 are flipped or rotated for display.
  int orientation = 1;
  // More than subimage 0: a multi-part EXR, a multi-page TIFF (other formats say false).
  bool more_subimages = false;
};

// An open image file: its header first, so that callers can refuse absurd sizes before any
// pixel is decoded.
class ImageSource {
 public:
  virtual ~ImageSource() = default;
  virtual const ImageHeader& header() const = 0;
  // Channels [0, channels) of every pixel, interleaved, top row first, converted to `type`
  // (uint8 and float32 only) into `out`. False on failure, a partial read included (a file that
  // ends early), with the reason in error().
  virtual bool read(int channels, PixelType type, void* out) = 0;
  // Channels [begin, end) the same way, in any of the types (uint32 too: exact integers).
  virtual bool read_channels(int begin, int end, PixelType type, void* out) = 0;
  virtual std::string error() = 0;
};

// How a float image is stored.
struct ImageWriteSpec {
  int width = 0, height = 0;
  // Where the pixels lie in the full image (EXR data and display windows); a full size of 0 is
  // the image itself.
  int x = 0, y = 0, full_width = 0, full_height = 0;
  // One per channel of the pixels given. "A" is alpha: straight (unassociated) in 8- and 16-bit
  // images, as PNG and TIFF store it; associated (premultiplied) in float ones, as EXR's.
  std::vector<std::string> channel_names;
  PixelType type = PixelType::uint8;       // what the file stores (values quantized as given)
  // When set, one per channel, float32 or uint32: the pixels are 4-byte values of these types,
  // stored as they are (a shard's exact accumulators beside its float color), and `type` is unused.
  std::vector<PixelType> channel_types;
  std::string color_space;                 // recorded in the file when not empty
  bool zip = false;                        // lossless zip compression (EXR)
  ImageMetadata metadata;                  // recorded in the file (EXR: header attributes)
};

// OpenImageIO's ImageBufAlgo::compare over two float images of the same layout.
struct PixelDifference {
  double mean_error = 0, rms_error = 0, psnr = 0, max_error = 0;
  int max_x = 0, max_y = 0, max_channel = 0;
  size_t warn_pixels = 0, fail_pixels = 0;  // pixels with any channel over the threshold
  std::string error;                        // set only when the comparison itself broke
};

struct ImageIoModule {
  uint32_t interface_version;
  // The file opened, or null with the reason (one line) in `error`.
  std::unique_ptr<ImageSource> (*open)(const std::string& path, std::string& error);
  // Whether OpenImageIO has a writer for `path`'s extension.
  bool (*can_write)(const std::string& path);
  // Writes `pixels` (spec.channel_names.size() floats per pixel, or 4-byte values of
  // spec.channel_types) in the format `path`'s extension names to the open file `descriptor`,
  // whose name is `path`. Formats that cannot write through
  // a descriptor (OpenImageIO's SGI, ICO, FITS, HEIF, RLA, zfile, and TIFF) open `path` by name. Returns ""
  // or the reason.
  std::string (*write)(int descriptor, const std::string& path, const ImageWriteSpec& spec, const void* pixels);
  PixelDifference (*compare)(const float* a, const float* b, int width, int height, int channels,
                             float fail_threshold, float warn_threshold);
};

// Raised whenever the struct above changes, so that a stale module is refused, not misread.
constexpr uint32_t image_io_interface_version = 5;

}  // namespace radiant

// The module's one exported symbol.
extern "C" const radiant::ImageIoModule* radiant_image_io_module();
