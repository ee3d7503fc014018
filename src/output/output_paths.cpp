#include "output/output_paths.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "output/output_target.h"

namespace radiant {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const std::string& target, const std::string& why) {
  throw std::runtime_error("cannot write '" + target + "': " + why);
}

// The folder a relative file name without one lives in.
std::string folder_of(const std::string& path) {
  std::string folder = fs::path(path).parent_path().string();
  return folder.empty() ? "." : folder;
}

// Throws unless `folder` is an existing folder this process may create files in.
void check_writable_folder(const std::string& target, const std::string& folder) {
  struct stat status;
  if (stat(folder.c_str(), &status) != 0) {
    if (errno == ENOENT) fail(target, "the folder '" + folder + "' does not exist");
    fail(target, "the folder '" + folder + "': " + std::strerror(errno));
  }
  if (!S_ISDIR(status.st_mode)) fail(target, "'" + folder + "' is not a folder");
  // AT_EACCESS: the effective ids, which the kernel checks when the file is created.
  if (faccessat(AT_FDCWD, folder.c_str(), W_OK | X_OK, AT_EACCESS) != 0)
    fail(target, "the folder '" + folder + "' is not writable (" + std::strerror(errno) + ")");
}

}  // namespace

void check_output_place(const std::string& target) {
  if (is_standard_output(target)) {
    if (fcntl(STDOUT_FILENO, F_GETFL) == -1) fail("standard output", "it is closed");
    return;
  }
  OutputTarget resolved = resolve_output_target(target);
  if (resolved.kind == OutputKind::file) check_writable_folder(target, folder_of(resolved.path));
}

void check_output_folder(const std::string& folder) {
  std::string existing = folder;
  struct stat status;
  while (stat(existing.c_str(), &status) != 0 && errno == ENOENT && existing != ".") existing = folder_of(existing);
  check_writable_folder(folder, existing);
}

DistinctFiles::Key DistinctFiles::key_of(const std::string& path) {
  Key key;
  if (is_standard_output(path)) {
    key.normal_path = "<standard output>";  // no path names it
    return key;
  }
  struct stat status;
  if (stat(path.c_str(), &status) == 0) {
    key.exists = true;
    key.device = status.st_dev;
    key.inode = status.st_ino;
    return key;
  }
  std::error_code error;
  fs::path normal = fs::weakly_canonical(fs::absolute(path), error);
  key.normal_path = error ? fs::absolute(path).lexically_normal().string() : normal.string();
  return key;
}

void DistinctFiles::add_input(const NamedFile& file) {
  if (file.path != "-") files_.emplace(key_of(file.path), file);  // "-" is standard input
}

void DistinctFiles::add_output(const NamedFile& file) {
  auto [at, added] = files_.emplace(key_of(file.path), file);
  if (!added)
    throw std::invalid_argument(file.name + " '" + file.path + "' is the same file as " + at->second.name + " '" +
                                at->second.path + "'");
}

void check_outputs_spare_scene_files(const std::vector<std::string>& scene_files, const std::vector<NamedFile>& outputs) {
  DistinctFiles files;
  for (const std::string& path : scene_files) files.add_input({"a file the scene reads", path});
  for (const NamedFile& output : outputs) files.add_output(output);
}

}  // namespace radiant
