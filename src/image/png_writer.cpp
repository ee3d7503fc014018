#include "image/png_writer.h"

#include <png.h>
#include <zlib.h>

#include <cstring>

#include "image/image_io.h"

namespace radiant {

namespace {

// OpenImageIO's float to uint8 conversion: scaled, rounded half away from zero, clamped.
uint8_t quantize(float value) {
  float scaled = value * 255.0f + 0.5f;
  if (!(scaled > 0)) return 0;  // negative, and NaN
  return scaled >= 255 ? 255 : uint8_t(scaled);
}

void append_big_endian(std::vector<unsigned char>& bytes, uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8) bytes.push_back((unsigned char)(value >> shift));
}

// A tEXt chunk: length, type, keyword NUL text, CRC of type and data.
std::vector<unsigned char> text_chunk(const std::string& keyword, const std::string& text) {
  std::vector<unsigned char> chunk;
  append_big_endian(chunk, uint32_t(keyword.size() + 1 + text.size()));
  for (char c : "tEXt" + keyword) chunk.push_back((unsigned char)c);
  chunk.push_back(0);
  chunk.insert(chunk.end(), text.begin(), text.end());
  append_big_endian(chunk, uint32_t(crc32(0, chunk.data() + 4, uInt(chunk.size() - 4))));
  return chunk;
}

// The signature (8 bytes) and IHDR (25 bytes) come first; text chunks may follow at once.
constexpr size_t after_header = 33;

}  // namespace

bool writes_as_png(const std::string& path, const ImageWriteSpec& spec) {
  size_t channels = spec.channel_names.size();
  return spec.type == PixelType::uint8 && spec.channel_types.empty() && (channels == 1 || channels == 3 || channels == 4) &&
         lowercase_extension(path) == ".png";
}

std::vector<unsigned char> encode_png(const ImageWriteSpec& spec, const float* pixels, std::string& error) {
  size_t channels = spec.channel_names.size();
  std::vector<uint8_t> values(size_t(spec.width) * size_t(spec.height) * channels);
  for (size_t i = 0; i < values.size(); ++i) values[i] = quantize(pixels[i]);
  // libpng's simplified API marks 8-bit images sRGB, reports errors in `message` and cleans up.
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  image.width = png_uint_32(spec.width);
  image.height = png_uint_32(spec.height);
  // libpng's 8-bit formats with alpha take it straight (not premultiplied), as PNG stores it.
  image.format = channels == 1 ? PNG_FORMAT_GRAY : channels == 4 ? PNG_FORMAT_RGBA : PNG_FORMAT_RGB;
  std::vector<unsigned char> bytes(PNG_IMAGE_PNG_SIZE_MAX(image));
  png_alloc_size_t size = bytes.size();
  if (!png_image_write_to_memory(&image, bytes.data(), &size, 0, values.data(), 0, nullptr)) {
    error = image.message[0] ? image.message : "PNG encoding failed";
    return {};
  }
  bytes.resize(size);
  for (const auto& [keyword, text] : spec.metadata) {
    std::vector<unsigned char> chunk = text_chunk(keyword, text);
    bytes.insert(bytes.begin() + after_header, chunk.begin(), chunk.end());
  }
  return bytes;
}

}  // namespace radiant
