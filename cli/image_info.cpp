#include "image_info.h"

#include <algorithm>
#include <array>
#include <fstream>

#include "image/image_format.h"
#include "image/image_io.h"
#include "image/render_metadata.h"
#include "json_output.h"
#include "memory/input_file.h"
#include "option_parsing.h"

namespace radiant::cli {

namespace {

// The formats radiant's readers know by their first bytes.
bool has_image_signature(const std::string& path) {
  uint64_t size = 0;
  if (!input_file_problem(path, size).empty()) return false;  // a FIFO would block: the opener refuses it
  std::array<char, 4> head{};
  std::ifstream in(path, std::ios::binary);
  if (!in.read(head.data(), head.size())) return false;
  std::string start(head.data(), head.size());
  return start == "\x89PNG" || start == "\x76\x2f\x31\x01" || start == "II*" + std::string(1, '\0') ||
         start == "MM" + std::string(1, '\0') + "*" || start.compare(0, 3, "\xFF\xD8\xFF") == 0 ||
         start.compare(0, 2, "#?") == 0;
}

const char* pixel_type_name(PixelType type) {
  switch (type) {
    case PixelType::uint8: return "uint8";
    case PixelType::uint16: return "uint16";
    case PixelType::half: return "half";
    case PixelType::float32: return "float";
    case PixelType::uint32: return "uint32";
    case PixelType::other: break;
  }
  return "other";
}

// "half", or "mixed" when the channels differ (a shard's float color beside uint32 sums).
std::string pixel_type_of(const ImageHeader& header) {
  if (header.channel_types.empty()) return "other";
  bool uniform = std::all_of(header.channel_types.begin(), header.channel_types.end(),
                             [&](PixelType type) { return type == header.channel_types.front(); });
  return uniform ? pixel_type_name(header.channel_types.front()) : "mixed";
}

const char* no_metadata_note = "no radiant metadata (not written by radiant, or written with --no-metadata)";

void print_text(std::ostream& out, const std::string& path, const ImageHeader& h, const ImageMetadata& ours) {
  out << path << "\n  size:     " << h.width << "x" << h.height;
  if (h.x != 0 || h.y != 0 || h.full_width != h.width || h.full_height != h.height)
    out << " at (" << h.x << ", " << h.y << ") of " << h.full_width << "x" << h.full_height;
  out << "\n  channels: " << h.channels << " (";
  for (size_t c = 0; c < h.channel_names.size(); ++c) out << (c ? ", " : "") << h.channel_names[c];
  out << ")\n  pixels:   " << pixel_type_of(h) << (h.color_space.empty() ? "" : ", " + h.color_space) << "\n";
  if (ours.empty()) {
    out << "  " << no_metadata_note << "\n";
    return;
  }
  out << "  metadata:\n";
  for (const auto& [key, value] : ours) out << "    " << key << ": " << value << "\n";
}

std::string json_of(const std::string& path, const ImageHeader& h, const ImageMetadata& ours) {
  Json j;
  j["image"] = path;
  j["width"] = h.width;
  j["height"] = h.height;
  j["window"] = {{"x", h.x}, {"y", h.y}, {"full_width", h.full_width}, {"full_height", h.full_height}};
  Json channels = Json::array();
  for (size_t c = 0; c < h.channel_names.size(); ++c)
    channels.push_back({{"name", h.channel_names[c]},
                        {"type", c < h.channel_types.size() ? pixel_type_name(h.channel_types[c]) : "other"}});
  j["channels"] = channels;
  j["pixel_type"] = pixel_type_of(h);
  j["color_space"] = h.color_space;
  Json metadata = Json::object();
  for (const auto& [key, value] : ours) metadata[key] = value;
  j["metadata"] = ours.empty() ? Json(nullptr) : metadata;
  return json_text(j);
}

}  // namespace

bool is_image_path(const std::string& path) {
  std::string extension = lowercase_extension(path);
  if (path == "-" || extension == ".scene" || extension == ".gltf" || extension == ".glb" || extension == ".obj")
    return false;
  return has_image_signature(path) || is_known_image_extension(path);
}

void print_image_info(std::ostream& out, const std::string& path, bool json) {
  MemoryBudget budget = command_memory_budget(std::nullopt);
  ImageHeader header = read_image_header(path, &budget);
  ImageMetadata ours = radiant_attributes(header.metadata);
  if (json) out << json_of(path, header, ours);
  else print_text(out, path, header, ours);
}

}  // namespace radiant::cli
