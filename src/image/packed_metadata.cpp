#include "image/packed_metadata.h"

#include <sstream>

namespace radiant {

namespace {

constexpr const char* packed_header = "radiant metadata\n";

std::string unescaped(const std::string& text) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\' && i + 1 < text.size()) out += text[++i] == 'n' ? '\n' : text[i];
    else out += text[i];
  }
  return out;
}

}  // namespace

std::string escaped_metadata_value(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '\\' ? "\\\\" : c == '\n' ? "\\n" : std::string(1, c);
  return out;
}

ImageMetadata packed_metadata(const ImageMetadata& metadata) {
  if (metadata.empty()) return {};
  ImageMetadata packed;
  std::string description = packed_header;
  for (const auto& [name, value] : metadata) {
    if (name == "Software") packed.emplace_back(name, value);
    description += name + ": " + escaped_metadata_value(value) + "\n";
  }
  packed.emplace_back("ImageDescription", description);
  return packed;
}

ImageMetadata unpacked_metadata(const ImageMetadata& metadata) {
  ImageMetadata unpacked;
  for (const auto& [name, value] : metadata) {
    if (value.rfind(packed_header, 0) != 0) {
      unpacked.emplace_back(name, value);
      continue;
    }
    std::istringstream lines(value.substr(std::string(packed_header).size()));
    for (std::string line; std::getline(lines, line);)
      if (size_t colon = line.find(": "); colon != std::string::npos)
        unpacked.emplace_back(line.substr(0, colon), unescaped(line.substr(colon + 2)));
  }
  // Software packed and kept as a tag: once.
  ImageMetadata once;
  for (const auto& attribute : unpacked) {
    bool seen = false;
    for (const auto& kept : once) seen = seen || kept == attribute;
    if (!seen) once.push_back(attribute);
  }
  return once;
}

}  // namespace radiant
