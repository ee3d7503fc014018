#include "image/exr_writer.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <map>

#include "image/image_format.h"

namespace radiant {

namespace {

constexpr uint32_t exr_magic = 20000630;  // 76 2f 31 01, little-endian
constexpr uint32_t long_names_flag = 0x400;
constexpr size_t short_name_limit = 31, long_name_limit = 255;
constexpr int zip_lines_per_chunk = 16;
// zlib's level 4: a 512² render came out within 0.1% of level 6's size and of OpenImageIO's own
// file (2,902,071 bytes against 2,898,952 and 2,902,246).
constexpr int zip_level = 4;

// The attributes every scanline file has; metadata may not take their names.
constexpr const char* reserved_names[] = {"channels",         "compression",        "dataWindow",
                                          "displayWindow",    "lineOrder",          "pixelAspectRatio",
                                          "screenWindowCenter", "screenWindowWidth", "tiles",
                                          "type",             "chunkCount",         "version"};

// OpenEXR's pixel type codes.
int exr_type_code(PixelType type) { return type == PixelType::uint32 ? 0 : type == PixelType::half ? 1 : 2; }

// A float as an IEEE half, rounded to nearest with ties to even; overflow becomes infinity and
// NaN stays NaN (quiet, keeping the payload's top bits).
uint16_t half_from_float(float value) {
  uint32_t bits = std::bit_cast<uint32_t>(value);
  uint16_t sign = uint16_t(bits >> 16 & 0x8000u);
  uint32_t magnitude = bits & 0x7fffffffu;
  if (magnitude > 0x7f800000u) return uint16_t(sign | 0x7e00u | (magnitude >> 13 & 0x3ffu));
  if (magnitude >= 0x477ff000u) return uint16_t(sign | 0x7c00u);  // 65520 and up round past 65504
  if (magnitude >= 0x38800000u) {                                  // a normal half (2^-14 and up)
    uint32_t rebiased = magnitude - 0x38000000u;                    // exponent bias 127 -> 15
    return uint16_t(sign | (rebiased + 0xfffu + (rebiased >> 13 & 1u)) >> 13);
  }
  int exponent = int(magnitude >> 23);
  if (exponent < 102) return sign;  // below 2^-25: rounds to zero
  // A subnormal half counts units of 2^-24: the float's significand shifted into them.
  uint32_t significand = (magnitude & 0x7fffffu) | 0x800000u;
  int shift = 126 - exponent;
  uint32_t units = significand >> shift, rest = significand & ((1u << shift) - 1), tie = 1u << (shift - 1);
  if (rest > tie || (rest == tie && (units & 1u))) ++units;
  return uint16_t(sign | units);
}

class Bytes {
 public:
  std::vector<unsigned char> data;
  void u8(uint8_t v) { data.push_back(v); }
  void u32(uint32_t v) {
    for (int shift = 0; shift < 32; shift += 8) data.push_back((unsigned char)(v >> shift));
  }
  void u64(uint64_t v) {
    for (int shift = 0; shift < 64; shift += 8) data.push_back((unsigned char)(v >> shift));
  }
  void f32(float v) { u32(std::bit_cast<uint32_t>(v)); }
  void text(const std::string& s) { data.insert(data.end(), s.begin(), s.end()); }
  void name(const std::string& s) { text(s), u8(0); }
};

struct Channel {
  std::string name;
  PixelType type;
  size_t source;  // its index among the pixels' values
};

// One chunk's scanlines as OpenEXR lays them out: each line, each channel in turn, every pixel.
void pack_lines(const ImageWriteSpec& spec, const std::vector<Channel>& channels, const void* pixels, int first,
                int lines, std::vector<unsigned char>& out) {
  size_t stride = spec.channel_names.size();
  const unsigned char* values = static_cast<const unsigned char*>(pixels);
  out.clear();
  for (int y = first; y < first + lines; ++y)
    for (const Channel& channel : channels)
      for (int x = 0; x < spec.width; ++x) {
        const unsigned char* value = values + ((size_t(y) * size_t(spec.width) + size_t(x)) * stride + channel.source) * 4;
        if (channel.type == PixelType::half) {
          float f;
          std::memcpy(&f, value, 4);
          uint16_t h = half_from_float(f);
          out.push_back((unsigned char)h), out.push_back((unsigned char)(h >> 8));
        } else {
          out.insert(out.end(), value, value + 4);  // float or uint32 as given, little-endian
        }
      }
}

// OpenEXR's ZIP: bytes split into even and odd halves, each byte replaced by its difference from
// the previous one, then deflated. Stored raw when that is not smaller (readers tell the two
// apart by the size).
std::vector<unsigned char> zip_chunk(const std::vector<unsigned char>& raw) {
  size_t size = raw.size();
  std::vector<unsigned char> split(size);
  size_t half = (size + 1) / 2;
  for (size_t i = 0; i < size; ++i) split[i % 2 ? half + i / 2 : i / 2] = raw[i];
  for (size_t i = size; i-- > 1;) split[i] = (unsigned char)(int(split[i]) - int(split[i - 1]) + 128 + 256);
  uLongf packed_size = compressBound(uLong(size));
  std::vector<unsigned char> packed(packed_size);
  if (compress2(packed.data(), &packed_size, split.data(), uLong(size), zip_level) != Z_OK || packed_size >= size)
    return raw;
  packed.resize(packed_size);
  return packed;
}

}  // namespace

bool writes_as_exr(const std::string& path, const ImageWriteSpec& spec) {
  if (image_format_of(path).writer != ImageWriterKind::exr || spec.channel_names.empty()) return false;
  if (spec.channel_types.empty()) return spec.type == PixelType::half || spec.type == PixelType::float32;
  return spec.channel_types.size() == spec.channel_names.size() &&
         std::all_of(spec.channel_types.begin(), spec.channel_types.end(),
                     [](PixelType t) { return t == PixelType::float32 || t == PixelType::uint32; });
}

std::string write_exr(TemporaryFile& file, const ImageWriteSpec& spec, const void* pixels) {
  std::vector<Channel> channels;
  for (size_t c = 0; c < spec.channel_names.size(); ++c)
    channels.push_back({spec.channel_names[c], spec.channel_types.empty() ? spec.type : spec.channel_types[c], c});
  std::sort(channels.begin(), channels.end(), [](const Channel& a, const Channel& b) { return a.name < b.name; });
  for (size_t c = 0; c < channels.size(); ++c)
    if (channels[c].name.empty() || (c > 0 && channels[c].name == channels[c - 1].name)) {
      return channels[c].name.empty() ? "a channel has no name" : "two channels are named '" + channels[c].name + "'";
    }

  // Attributes in name order, as OpenEXR's own header keeps them; metadata by its last value.
  std::map<std::string, std::string> strings;
  for (const auto& [name, value] : spec.metadata) {
    if (name.empty() || std::find(std::begin(reserved_names), std::end(reserved_names), name) != std::end(reserved_names)) {
      return name.empty() ? "an attribute has no name" : "the attribute name '" + name + "' is reserved by OpenEXR";
    }
    strings[name] = value;
  }
  size_t longest = 0;
  for (const Channel& channel : channels) longest = std::max(longest, channel.name.size());
  for (const auto& entry : strings) longest = std::max(longest, entry.first.size());
  if (longest > long_name_limit)
    return "a channel or attribute name is longer than OpenEXR's " + std::to_string(long_name_limit) + " bytes";

  int full_width = spec.full_width > 0 ? spec.full_width : spec.width;
  int full_height = spec.full_height > 0 ? spec.full_height : spec.height;
  std::map<std::string, std::pair<std::string, Bytes>> attributes;  // name -> type, value
  auto add = [&](const std::string& name, const std::string& type) -> Bytes& {
    auto& slot = attributes[name];
    slot.first = type;
    return slot.second;
  };
  Bytes& list = add("channels", "chlist");
  for (const Channel& channel : channels) {
    list.name(channel.name);
    list.u32(uint32_t(exr_type_code(channel.type)));
    list.u32(0);  // pLinear and three reserved bytes
    list.u32(1), list.u32(1);  // x and y sampling
  }
  list.u8(0);
  add("compression", "compression").u8(spec.zip ? 3 : 0);
  Bytes& data_window = add("dataWindow", "box2i");
  for (int v : {spec.x, spec.y, spec.x + spec.width - 1, spec.y + spec.height - 1}) data_window.u32(uint32_t(v));
  Bytes& display_window = add("displayWindow", "box2i");
  for (int v : {0, 0, full_width - 1, full_height - 1}) display_window.u32(uint32_t(v));
  add("lineOrder", "lineOrder").u8(0);  // increasing y
  add("pixelAspectRatio", "float").f32(1);
  Bytes& center = add("screenWindowCenter", "v2f");
  center.f32(0), center.f32(0);
  add("screenWindowWidth", "float").f32(1);
  for (const auto& [name, value] : strings) add(name, "string").text(value);

  Bytes header;
  header.u32(exr_magic);
  header.u32(2 | (longest > short_name_limit ? long_names_flag : 0));
  for (const auto& [name, typed] : attributes) {
    header.name(name);
    header.name(typed.first);
    header.u32(uint32_t(typed.second.data.size()));
    header.data.insert(header.data.end(), typed.second.data.begin(), typed.second.data.end());
  }
  header.u8(0);

  // The chunks' offsets are known only once each is compressed: the table is written last, in
  // the place left for it.
  int lines_per_chunk = spec.zip ? zip_lines_per_chunk : 1;
  int chunk_count = (spec.height + lines_per_chunk - 1) / lines_per_chunk;
  uint64_t table_at = header.data.size();
  header.data.resize(header.data.size() + size_t(chunk_count) * 8);
  file.write(header.data.data(), header.data.size());
  Bytes table;
  uint64_t offset = header.data.size();
  // Chunks are packed and compressed a batch at a time on the arena's threads, then written in
  // order: a batch is no larger than the threads can work on at once, nor than 64 MiB of lines.
  size_t line_bytes = 0;
  for (const Channel& channel : channels) line_bytes += size_t(spec.width) * (channel.type == PixelType::half ? 2 : 4);
  size_t chunk_bytes = std::max<size_t>(1, line_bytes * size_t(lines_per_chunk));
  int batch = int(std::clamp<size_t>((size_t(64) << 20) / chunk_bytes, 1, size_t(tbb::this_task_arena::max_concurrency())));
  std::vector<std::vector<unsigned char>> stored(static_cast<size_t>(batch));
  for (int start = 0; start < chunk_count; start += batch) {
    int end = std::min(chunk_count, start + batch);
    tbb::parallel_for(start, end, [&](int chunk) {
      int first = chunk * lines_per_chunk, lines = std::min(lines_per_chunk, spec.height - first);
      std::vector<unsigned char>& out = stored[size_t(chunk - start)];
      pack_lines(spec, channels, pixels, first, lines, out);
      if (spec.zip) out = zip_chunk(out);
    });
    for (int chunk = start; chunk < end; ++chunk) {
      const std::vector<unsigned char>& bytes = stored[size_t(chunk - start)];
      Bytes prefix;
      prefix.u32(uint32_t(spec.y + chunk * lines_per_chunk));
      prefix.u32(uint32_t(bytes.size()));
      file.write(prefix.data.data(), prefix.data.size());
      file.write(bytes.data(), bytes.size());
      table.u64(offset);
      offset += prefix.data.size() + bytes.size();
    }
  }
  file.write_at(table_at, table.data.data(), table.data.size());
  return "";
}

}  // namespace radiant
