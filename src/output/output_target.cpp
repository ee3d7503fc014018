#include "output/output_target.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace radiant {

namespace {

[[noreturn]] void refuse(const std::string& target, const std::string& why) {
  throw std::runtime_error("cannot write '" + target + "': " + why);
}

}  // namespace

OutputTarget resolve_output_target(const std::string& target) {
  struct stat link_status, status;
  if (lstat(target.c_str(), &link_status) != 0) {
    if (errno == ENOENT) return {OutputKind::file, target};
    refuse(target, std::strerror(errno));
  }
  bool symlink = S_ISLNK(link_status.st_mode);
  if (stat(target.c_str(), &status) != 0) {
    if (symlink && errno == ENOENT) refuse(target, "it is a symbolic link to a missing file");
    refuse(target, std::strerror(errno));
  }
  std::string path = target;
  if (symlink) {
    std::error_code error;
    path = std::filesystem::canonical(target, error).string();
    if (error) refuse(target, "cannot resolve the symbolic link: " + error.message());
  }
  if (S_ISDIR(status.st_mode)) refuse(target, "it is a folder");
  if (S_ISCHR(status.st_mode) || S_ISFIFO(status.st_mode)) {
    if (faccessat(AT_FDCWD, path.c_str(), W_OK, AT_EACCESS) != 0) refuse(target, "it is not writable");
    return {OutputKind::stream, path};
  }
  if (!S_ISREG(status.st_mode))
    refuse(target, std::string("it is a ") + (S_ISBLK(status.st_mode) ? "block device" : "socket") +
                       "; radiant writes regular files, character devices and FIFOs");
  // Root may write any file: the mode bits still say the file is not meant to change.
  if ((status.st_mode & 0222) == 0 || faccessat(AT_FDCWD, path.c_str(), W_OK, AT_EACCESS) != 0)
    refuse(target, "it is read-only");
  return {OutputKind::file, path};
}

}  // namespace radiant
