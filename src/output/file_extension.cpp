#include "output/file_extension.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace radiant {

std::string lowercase_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return extension;
}

}  // namespace radiant
