#include "image/png_writer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "image/image_format.h"
#include "image/parallel_deflate.h"

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

// A chunk: length, type, data, and the CRC of type and data.
void append_chunk(std::vector<unsigned char>& file, const char* type, const unsigned char* data, size_t size) {
  append_big_endian(file, uint32_t(size));
  file.insert(file.end(), type, type + 4);
  file.insert(file.end(), data, data + size);
  uLong crc = crc32(0, reinterpret_cast<const Bytef*>(type), 4);
  if (size > 0) crc = crc32(crc, data, uInt(size));  // zlib's crc32 restarts on a null buffer
  append_big_endian(file, uint32_t(crc));
}

// A text chunk. ASCII text, and text that is not UTF-8 (its bytes kept, which tEXt reads as
// Latin-1), goes in tEXt; UTF-8 beyond ASCII (a file name in Greek) in iTXt, uncompressed, as
// PNG asks.
void append_text_chunk(std::vector<unsigned char>& file, const std::string& keyword, const std::string& text) {
  bool ascii = std::all_of(text.begin(), text.end(), [](char c) { return (unsigned char)c < 0x80; });
  bool international = !ascii && is_utf8(text);
  std::string data = keyword + '\0';
  // iTXt: not compressed, compression method 0, no language tag, no translated keyword.
  if (international) data += std::string("\0\0\0\0", 4);
  data += text;
  append_chunk(file, international ? "iTXt" : "tEXt", reinterpret_cast<const unsigned char*>(data.data()), data.size());
}

// One row of display values as 8-bit samples.
void quantize_row(const float* pixels, size_t length, uint8_t* out) {
  for (size_t i = 0; i < length; ++i) out[i] = quantize(pixels[i]);
}

// PNG's Paeth predictor: whichever neighbour is nearest to left + above - above_left.
int paeth(int left, int above, int above_left) {
  int estimate = left + above - above_left;
  int to_left = std::abs(estimate - left), to_above = std::abs(estimate - above), to_corner = std::abs(estimate - above_left);
  return to_left <= to_above && to_left <= to_corner ? left : to_above <= to_corner ? above : above_left;
}

// `row` filtered with `predict` (of the bytes to the left, above and above-left; zeros outside the
// image) into `out`; returns the filtered bytes' summed magnitude, read as signed.
template <class Predict>
uint64_t filter_with(const uint8_t* row, const uint8_t* above, size_t length, size_t bpp, uint8_t* out, Predict predict) {
  uint64_t sum = 0;
  for (size_t i = 0; i < length; ++i) {
    bool first = i < bpp;
    uint8_t value = uint8_t(row[i] - predict(first ? 0 : row[i - bpp], above[i], first ? 0 : above[i - bpp]));
    out[i] = value;
    sum += value < 128 ? value : 256 - value;
  }
  return sum;
}

// `row` through PNG's five filters (None, Sub, Up, Average, Paeth) against the row above it
// (zeros above the first), `bpp` bytes a pixel, into `out`: the filter's type, then the bytes of
// the filter whose output, read as signed, sums to the least magnitude (libpng's choice too: it
// favours the small differences deflate codes best). `candidates` holds 5 x length bytes.
void filter_row(const uint8_t* row, const uint8_t* above, size_t length, size_t bpp, uint8_t* candidates, uint8_t* out) {
  uint64_t sums[5] = {
      filter_with(row, above, length, bpp, candidates, [](int, int, int) { return 0; }),
      filter_with(row, above, length, bpp, candidates + length, [](int left, int, int) { return left; }),
      filter_with(row, above, length, bpp, candidates + 2 * length, [](int, int up, int) { return up; }),
      filter_with(row, above, length, bpp, candidates + 3 * length, [](int left, int up, int) { return (left + up) / 2; }),
      filter_with(row, above, length, bpp, candidates + 4 * length, paeth)};
  int best = int(std::min_element(sums, sums + 5) - sums);  // the first of equals
  out[0] = uint8_t(best);
  std::memcpy(out + 1, candidates + size_t(best) * length, length);
}

// Every row filtered, each prefixed by its filter type: the data PNG deflates. Rows are
// quantized and filtered in parallel, each block of rows quantizing the row above it again.
std::vector<uint8_t> filtered_rows(const float* pixels, size_t width, size_t height, size_t channels) {
  size_t length = width * channels;
  std::vector<uint8_t> rows(height * (length + 1));
  tbb::parallel_for(tbb::blocked_range<size_t>(0, height, 16), [&](const tbb::blocked_range<size_t>& range) {
    std::vector<uint8_t> above(length, 0), row(length), candidates(5 * length);
    if (range.begin() > 0) quantize_row(pixels + (range.begin() - 1) * length, length, above.data());
    for (size_t y = range.begin(); y < range.end(); ++y) {
      quantize_row(pixels + y * length, length, row.data());
      filter_row(row.data(), above.data(), length, channels, candidates.data(), &rows[y * (length + 1)]);
      std::swap(row, above);
    }
  });
  return rows;
}

}  // namespace

bool writes_as_png(const std::string& path, const ImageWriteSpec& spec) {
  size_t channels = spec.channel_names.size();
  return spec.type == PixelType::uint8 && spec.channel_types.empty() && (channels == 1 || channels == 3 || channels == 4) &&
         image_format_of(path).writer == ImageWriterKind::png;
}

std::vector<unsigned char> encode_png(const ImageWriteSpec& spec, const float* pixels, std::string& error) {
  size_t channels = spec.channel_names.size(), width = size_t(spec.width), height = size_t(spec.height);
  std::vector<uint8_t> rows = filtered_rows(pixels, width, height, channels);
  std::vector<std::vector<unsigned char>> stream = deflate_in_pieces(rows.data(), rows.size());
  if (stream.empty()) {
    error = "PNG encoding failed: zlib could not compress the image";
    return {};
  }
  rows = {};
  std::vector<unsigned char> file = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::vector<unsigned char> header;
  append_big_endian(header, uint32_t(width));
  append_big_endian(header, uint32_t(height));
  // 8 bits; gray, RGB or RGBA (straight alpha, as PNG stores it); deflate, adaptive filters, not
  // interlaced.
  uint8_t color_type = channels == 1 ? 0 : channels == 4 ? 6 : 2;
  header.insert(header.end(), {8, color_type, 0, 0, 0});
  append_chunk(file, "IHDR", header.data(), header.size());
  for (const auto& [keyword, text] : spec.metadata) append_text_chunk(file, keyword, text);
  const unsigned char perceptual = 0;  // sRGB, rendering intent perceptual
  append_chunk(file, "sRGB", &perceptual, 1);
  for (const std::vector<unsigned char>& segment : stream) append_chunk(file, "IDAT", segment.data(), segment.size());
  append_chunk(file, "IEND", nullptr, 0);
  return file;
}

}  // namespace radiant
