#include "image/png_writer.h"

#include <png.h>

#include <cstring>
#include <vector>

#include "image/image_io.h"

namespace radiant {

namespace {

// OpenImageIO's float to uint8 conversion: scaled, rounded half away from zero, clamped.
uint8_t quantize(float value) {
  float scaled = value * 255.0f + 0.5f;
  if (!(scaled > 0)) return 0;  // negative, and NaN
  return scaled >= 255 ? 255 : uint8_t(scaled);
}

}  // namespace

bool writes_as_png(const std::string& path, const ImageWriteSpec& spec) {
  size_t channels = spec.channel_names.size();
  return spec.type == PixelType::uint8 && (channels == 1 || channels == 3) && lowercase_extension(path) == ".png";
}

std::string write_png(const std::string& path, const ImageWriteSpec& spec, const float* pixels) {
  if (!writes_as_png(path, spec)) return "the PNG writer stores 8-bit gray or RGB only";
  size_t channels = spec.channel_names.size();
  std::vector<uint8_t> bytes(size_t(spec.width) * size_t(spec.height) * channels);
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = quantize(pixels[i]);
  // libpng's simplified API marks 8-bit images sRGB, reports errors in `message` and cleans up.
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  image.width = png_uint_32(spec.width);
  image.height = png_uint_32(spec.height);
  image.format = channels == 1 ? PNG_FORMAT_GRAY : PNG_FORMAT_RGB;
  if (!png_image_write_to_file(&image, path.c_str(), 0, bytes.data(), 0, nullptr))
    return image.message[0] ? image.message : "PNG write failed";
  return "";
}

}  // namespace radiant
