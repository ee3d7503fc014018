#include "image/exr_header_check.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

namespace radiant {

namespace {

constexpr uint32_t exr_magic = 20000630;   // 76 2f 31 01, little-endian
constexpr uint32_t tiled_flag = 0x200;     // single-part tiled file
constexpr uint32_t long_names_flag = 0x400;
constexpr uint32_t multipart_flag = 0x1000;

// Little-endian reads that report a short file instead of reading past it.
struct Reader {
  std::ifstream in;
  uint64_t size = 0, at = 0;

  bool bytes(char* out, uint64_t count) {
    if (count > size - at || !in.read(out, std::streamsize(count))) return false;
    at += count;
    return true;
  }
  std::optional<uint32_t> u32() {
    unsigned char b[4];
    if (!bytes(reinterpret_cast<char*>(b), 4)) return std::nullopt;
    return uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
  }
  // A NUL-terminated name of at most `longest` characters ("" ends a header).
  std::optional<std::string> name(size_t longest) {
    std::string text;
    for (char c; bytes(&c, 1);) {
      if (c == '\0') return text;
      if (text.size() == longest) return std::nullopt;
      text += c;
    }
    return std::nullopt;
  }
};

int32_t as_int(uint32_t v) { return static_cast<int32_t>(v); }

// Scanlines per chunk of each compression (OpenEXR's table); unknown ones are taken as the
// largest, which gives the fewest chunks and so never refuses a valid file.
int64_t lines_per_chunk(int compression) {
  switch (compression) {
    case 0: case 1: case 2: return 1;     // none, RLE, ZIPS
    case 3: case 5: return 16;            // ZIP, PXR24
    case 4: case 6: case 7: case 8: return 32;  // PIZ, B44, B44A, DWAA
    default: return 256;                  // DWAB and unknown
  }
}

// What one part's header declares that decides its offset table.
struct Part {
  bool has_window = false;
  int64_t width = 0, height = 0;
  int compression = 0;
  bool tiled = false;
  int64_t tile_width = 0, tile_height = 0;
  int64_t bytes_per_pixel = 0;  // every channel at full resolution: subsampling only lowers it

  // A lower bound on its chunks, each of which has an 8-byte offset table entry. In double: a
  // hostile window's tile count does not fit in 64 bits.
  double minimum_chunks() const {
    if (tiled && tile_width > 0 && tile_height > 0)
      return double((width + tile_width - 1) / tile_width) * double((height + tile_height - 1) / tile_height);
    return double((height + lines_per_chunk(compression) - 1) / lines_per_chunk(compression));
  }
  // The unpacked bytes of its largest chunk, in double for the same reason.
  double chunk_bytes() const {
    double pixels = tiled ? double(tile_width) * double(tile_height)
                          : double(width) * double(std::min(height, lines_per_chunk(compression)));
    return pixels * double(bytes_per_pixel);
  }
};

// Bytes per pixel of a channel list: each entry a name, a pixel type (0 uint, 1 half, 2 float),
// four bytes of flags and two of sampling, the list ended by an empty name.
int64_t channel_list_bytes(Reader& reader, uint64_t end) {
  int64_t bytes = 0;
  while (reader.at < end) {
    std::optional<std::string> name = reader.name(255);
    if (!name || name->empty()) break;
    std::optional<uint32_t> type = reader.u32();
    char rest[12];
    if (!type || !reader.bytes(rest, sizeof rest)) break;
    bytes += *type == 1 ? 2 : 4;  // an unknown type as the widest: OpenEXR refuses it anyway
  }
  return bytes;
}

// Reads one header's attributes; "" or the problem.
std::string read_header(Reader& reader, size_t longest_name, bool tiled_file, Part& part, bool& empty) {
  part.tiled = tiled_file;
  empty = true;
  for (;;) {
    std::optional<std::string> name = reader.name(longest_name);
    if (!name) return "an attribute name is not terminated within the file or its length limit";
    if (name->empty()) return "";
    empty = false;
    std::optional<std::string> type = reader.name(longest_name);
    std::optional<uint32_t> declared = type ? reader.u32() : std::nullopt;
    if (!declared) return "attribute '" + *name + "' is cut short";
    int64_t size = as_int(*declared);
    uint64_t left = reader.size - reader.at;
    if (size < 0 || uint64_t(size) > left)
      return "attribute '" + *name + "' declares " + std::to_string(size) + " bytes, the file has " +
             std::to_string(left) + " left";
    uint64_t end = reader.at + uint64_t(size);
    if (*name == "dataWindow" && *type == "box2i" && size == 16) {
      int64_t box[4];
      for (int64_t& v : box) v = as_int(reader.u32().value_or(0));
      if (box[2] < box[0] || box[3] < box[1]) return "the data window is empty or inverted";
      part.has_window = true;
      part.width = box[2] - box[0] + 1;
      part.height = box[3] - box[1] + 1;
    } else if (*name == "channels" && *type == "chlist") {
      part.bytes_per_pixel = channel_list_bytes(reader, end);
    } else if (*name == "compression" && size == 1) {
      char c = 0;
      reader.bytes(&c, 1);
      part.compression = static_cast<unsigned char>(c);
    } else if (*name == "tiles" && size == 9) {
      part.tile_width = reader.u32().value_or(0);
      part.tile_height = reader.u32().value_or(0);
    } else if (*name == "type" && *type == "string") {
      std::string text(size_t(size), '\0');
      reader.bytes(text.data(), uint64_t(size));
      part.tiled = text.find("tiled") != std::string::npos;
    }
    reader.in.seekg(std::streamoff(end));
    reader.at = end;
  }
}

std::string header_problem(const std::string& path, uint64_t& decoder_bytes) {
  Reader reader;
  std::error_code ec;
  reader.size = std::filesystem::file_size(path, ec);
  if (ec) return "";  // the reader reports what is wrong with the file itself
  reader.in.open(path, std::ios::binary);
  std::optional<uint32_t> magic = reader.u32();
  if (!magic || *magic != exr_magic) return "";
  std::optional<uint32_t> version = reader.u32();
  if (!version) return "the header is cut short";
  size_t longest_name = (*version & long_names_flag) ? 255 : 31;
  bool multipart = *version & multipart_flag;
  double chunks = 0, decoded = 0;
  for (;;) {
    Part part;
    bool empty = false;
    std::string problem = read_header(reader, longest_name, *version & tiled_flag, part, empty);
    if (!problem.empty()) return problem;
    if (empty && multipart) break;  // the empty header that ends a multi-part file's headers
    if (!part.has_window) return "a header has no data window";
    chunks += part.minimum_chunks();
    decoded += 3 * part.chunk_bytes();
    if (!multipart) break;
  }
  uint64_t left = reader.size - reader.at;
  if (chunks > double(left / 8)) {
    char text[160];
    std::snprintf(text, sizeof text, "its data window needs %.4g chunks, more than the %llu bytes after its header can index",
                  chunks, static_cast<unsigned long long>(left));
    return text;
  }
  decoder_bytes = decoded >= 0x1p63 ? uint64_t(1) << 63 : uint64_t(decoded);
  return "";
}

}  // namespace

std::string exr_extent_problem(const std::string& path) {
  Reader reader;
  std::error_code ec;
  reader.size = std::filesystem::file_size(path, ec);
  if (ec) return "";
  reader.in.open(path, std::ios::binary);
  std::optional<uint32_t> magic = reader.u32(), version = reader.u32();
  if (!magic || *magic != exr_magic || !version || (*version & (multipart_flag | tiled_flag))) return "";
  Part part;
  bool empty = false;
  if (!read_header(reader, (*version & long_names_flag) ? 255 : 31, false, part, empty).empty() || !part.has_window ||
      part.tiled)
    return "";  // check_exr_header says what is wrong, or the layout is not one this walk knows
  uint64_t chunks = uint64_t((part.height + lines_per_chunk(part.compression) - 1) / lines_per_chunk(part.compression));
  if (chunks > (reader.size - reader.at) / 8) return "its offset table is cut short";
  uint64_t table_end = reader.at + 8 * chunks, last = 0;
  for (uint64_t i = 0; i < chunks; ++i) {
    std::optional<uint32_t> low = reader.u32(), high = reader.u32();
    uint64_t offset = uint64_t(*low) | uint64_t(*high) << 32;
    if (offset < table_end || offset > reader.size - std::min<uint64_t>(reader.size, 8))
      return "chunk " + std::to_string(i) + " starts at byte " + std::to_string(offset) + ", outside the file's " +
             std::to_string(reader.size) + " bytes";
    last = std::max(last, offset);
  }
  reader.in.seekg(std::streamoff(last));
  reader.at = last;
  std::optional<uint32_t> line = reader.u32(), packed = reader.u32();
  uint64_t end = last + 8 + packed.value_or(0);
  if (!line || !packed || end != reader.size)
    return "the file is " + std::to_string(reader.size) + " bytes but its last chunk ends at byte " + std::to_string(end) +
           " (cut short or extended)";
  return "";
}

ExrHeaderCheck check_exr_header(const std::string& path) {
  ExrHeaderCheck check;
  check.problem = header_problem(path, check.decoder_bytes);
  if (!check.problem.empty()) check.decoder_bytes = 0;
  return check;
}

}  // namespace radiant
