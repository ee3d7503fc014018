#include "load_scene.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "gltf/gltf_loader.h"
#include "obj/obj_loader.h"
#include "scene/validate.h"
#include "scene_format/scene_format_loader.h"

namespace radiant {

std::string one_line(const std::string& text) {
  std::istringstream lines(text);
  std::string line, out;
  while (std::getline(lines, line)) {
    while (!line.empty() && std::isspace((unsigned char)line.back())) line.pop_back();
    if (!line.empty()) out += (out.empty() ? "" : "; ") + line;
  }
  return out;
}

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    unsigned char byte = static_cast<unsigned char>(c);
    if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else if (c == '\t') out += "\\t";
    else if (byte < 0x20 || byte == 0x7F) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", byte);
      out += hex;
    } else out += c;
  }
  return out;
}

size_t default_max_memory() {
  long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return size_t(4) << 30;
  return size_t(pages) * size_t(page_size) / 4;
}

static std::string lowercase_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

SceneDesc load_scene(const std::string& path, const LoadOptions& given) {
  LoadOptions options = given;
  if (options.max_memory_bytes == 0) options.max_memory_bytes = default_max_memory();
  SceneDesc scene;
  if (path == "-") {
    scene = load_scene_format(std::cin, "<stdin>", std::filesystem::current_path().string(), options);
  } else {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
      throw LoadError(path + ": cannot open scene file (" +
                      (std::filesystem::exists(path, ec) ? "not a regular file" : "no such file") + ")");
    std::string ext = lowercase_extension(path);
    if (ext == ".gltf" || ext == ".glb") {
      scene = load_gltf(path, options);
    } else if (ext == ".obj") {
      scene = load_obj(path, options);
    } else if (ext == ".scene") {
      std::ifstream in(path, std::ios::binary);
      if (!in) throw LoadError(path + ": cannot open scene file");
      std::string base = std::filesystem::absolute(path).parent_path().string();
      scene = load_scene_format(in, path, base, options);
    } else {
      throw LoadError(path + ": unknown scene format '" + ext + "' (expected .scene, .gltf, .glb or .obj)");
    }
  }
  scene.source_path = path == "-" ? "<stdin>" : path;
  validate_scene(scene);
  return scene;
}

}  // namespace radiant
