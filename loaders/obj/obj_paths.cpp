#include "obj/obj_paths.h"

#include <algorithm>

namespace radiant {

std::string portable_path(const std::string& name) {
  std::string path = name;
  std::replace(path.begin(), path.end(), '\\', '/');
  return path;
}

std::map<std::string, std::string> mtllib_names(std::istream& in) {
  std::map<std::string, std::string> names;
  std::string line;
  while (std::getline(in, line)) {
    size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line.compare(start, 6, "mtllib") != 0) continue;
    if (start + 6 >= line.size() || (line[start + 6] != ' ' && line[start + 6] != '\t')) continue;
    // The split of tinyobjloader's SplitString: spaces separate, a backslash escapes.
    std::string asked, written;
    auto flush = [&] {
      if (!asked.empty()) names[asked] = written;
      asked.clear(), written.clear();
    };
    for (size_t i = start + 7; i < line.size(); ++i) {
      char c = line[i];
      if (c == '\r') continue;
      if (c == '\\' && i + 1 < line.size()) {
        char escaped_char = line[++i];
        asked += escaped_char;
        written += escaped_char == ' ' ? std::string(" ") : std::string("/") + escaped_char;
      } else if (c == ' ') {
        flush();
      } else {
        asked += c, written += c;
      }
    }
    flush();
  }
  return names;
}

std::string utf16_byte_order(const std::string& first_bytes) {
  if (first_bytes.size() < 2) return "";
  unsigned char a = static_cast<unsigned char>(first_bytes[0]), b = static_cast<unsigned char>(first_bytes[1]);
  if (a == 0xFE && b == 0xFF) return "UTF-16 big-endian";
  if (a == 0xFF && b == 0xFE) return "UTF-16 little-endian";
  // Without a byte order mark, ASCII text in UTF-16 alternates NUL bytes.
  if (a == 0 && b != 0) return "UTF-16 big-endian";
  if (a != 0 && b == 0) return "UTF-16 little-endian";
  return "";
}

}  // namespace radiant
