#include "memory/input_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

namespace radiant {

std::string input_file_problem(const std::filesystem::path& path, uint64_t& size) {
  struct stat info;
  if (stat(path.c_str(), &info) != 0)
    return errno == ENOENT || errno == ENOTDIR ? no_such_file : std::strerror(errno);
  if (S_ISDIR(info.st_mode)) return "is a directory";
  if (!S_ISREG(info.st_mode)) return "is not a regular file";
  size = uint64_t(info.st_size);
  return "";
}

}  // namespace radiant
