#include "image/png_writer.h"

#include <png.h>
#include <zlib.h>

#include <algorithm>
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

// Whether `text` is well-formed UTF-8: no stray continuation bytes, overlong forms, surrogates
// or code points past U+10FFFF.
bool is_utf8(const std::string& text) {
  static constexpr uint32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};  // by sequence length
  for (size_t i = 0; i < text.size();) {
    unsigned char lead = (unsigned char)text[i];
    size_t length = lead < 0x80 ? 1 : (lead >> 5) == 6 ? 2 : (lead >> 4) == 14 ? 3 : (lead >> 3) == 30 ? 4 : 0;
    if (length == 0 || i + length > text.size()) return false;
    uint32_t code = length == 1 ? lead : lead & (0x7Fu >> length);
    for (size_t k = 1; k < length; ++k) {
      unsigned char next = (unsigned char)text[i + k];
      if ((next >> 6) != 2) return false;
      code = code << 6 | (next & 0x3Fu);
    }
    if (code < smallest[length] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return false;
    i += length;
  }
  return true;
}

// A text chunk: length, type, data, CRC of type and data. ASCII text, and text that is not
// UTF-8 (its bytes kept, which tEXt reads as Latin-1), goes in tEXt; UTF-8 beyond ASCII (a
// file name in Greek) in iTXt, uncompressed, as PNG asks.
std::vector<unsigned char> text_chunk(const std::string& keyword, const std::string& text) {
  bool ascii = std::all_of(text.begin(), text.end(), [](char c) { return (unsigned char)c < 0x80; });
  bool international = !ascii && is_utf8(text);
  std::string data = keyword + '\0';
  // iTXt: not compressed, compression method 0, no language tag, no translated keyword.
  if (international) data += std::string("\0\0\0\0", 4);
  data += text;
  std::vector<unsigned char> chunk;
  append_big_endian(chunk, uint32_t(data.size()));
  for (char c : (international ? "iTXt" : "tEXt") + data) chunk.push_back((unsigned char)c);
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
  std::vector<unsigned char> chunks;  // in the order given
  for (const auto& [keyword, text] : spec.metadata) {
    std::vector<unsigned char> chunk = text_chunk(keyword, text);
    chunks.insert(chunks.end(), chunk.begin(), chunk.end());
  }
  bytes.insert(bytes.begin() + after_header, chunks.begin(), chunks.end());
  return bytes;
}

}  // namespace radiant
