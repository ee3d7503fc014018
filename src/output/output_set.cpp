#include "output/output_set.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "output/output_paths.h"
#include "output/output_target.h"

namespace radiant {

namespace {

// Copies a finished temporary into the open `descriptor`, every write checked; errors name
// `destination_name`.
void copy_into(const TemporaryFile& file, int descriptor, const std::string& destination_name) {
  std::ifstream in(file.path(), std::ios::binary);
  char buffer[1 << 16];
  while (in) {
    in.read(buffer, sizeof buffer);
    for (std::streamsize done = 0; done < in.gcount();) {
      ssize_t wrote = ::write(descriptor, buffer + done, size_t(in.gcount() - done));
      if (wrote < 0 && errno == EINTR) continue;
      if (wrote <= 0) throw std::runtime_error("cannot write to " + destination_name + ": " + std::strerror(errno));
      done += wrote;
    }
  }
  if (in.bad()) throw std::runtime_error("cannot read back '" + file.path() + "' for " + destination_name);
}

// Writes a finished temporary into a device or FIFO (opened only now: a FIFO's open waits for
// its reader) or to standard output.
void stream_out(const TemporaryFile& file, const std::string& destination) {
  if (is_standard_output(destination)) return copy_into(file, STDOUT_FILENO, "standard output");
  std::string name = "'" + file.target() + "'";
  int descriptor;
  while ((descriptor = open(destination.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC)) < 0 && errno == EINTR) {
  }
  if (descriptor < 0) file.fail(std::strerror(errno));
  try {
    copy_into(file, descriptor, name);
  } catch (...) {
    close(descriptor);
    throw;
  }
  if (close(descriptor) != 0) file.fail(std::strerror(errno));
}

}  // namespace

TemporaryFile& OutputSet::create(const std::string& target) {
  OutputTarget resolved = resolve_output_target(target);
  if (resolved.kind == OutputKind::stream)
    return create_streamed(target, std::filesystem::path(target).extension().string(), resolved.path);
  files_.push_back(std::make_unique<TemporaryFile>(target, resolved.path));
  return *files_.back();
}

TemporaryFile& OutputSet::create_standard_output(const std::string& extension) {
  return create_streamed("", "." + extension, "-");
}

TemporaryFile& OutputSet::create_streamed(const std::string& target, const std::string& extension,
                                          const std::string& destination) {
  std::filesystem::path folder = std::filesystem::temp_directory_path();
  std::string place = (folder / ("radiant-standard-output" + extension)).string();
  files_.push_back(std::make_unique<TemporaryFile>(target.empty() ? place : target, place));
  streams_.push_back({files_.back().get(), destination});
  return *files_.back();
}

void OutputSet::remove(const TemporaryFile& file) {
  std::erase_if(streams_, [&](const Stream& stream) { return stream.file == &file; });
  std::erase_if(files_, [&](const std::unique_ptr<TemporaryFile>& f) { return f.get() == &file; });
}

void OutputSet::commit() {
  for (auto& file : files_) file->finish();
  for (auto& file : files_) {
    auto stream = std::find_if(streams_.begin(), streams_.end(), [&](const Stream& s) { return s.file == file.get(); });
    if (stream != streams_.end()) stream_out(*file, stream->destination);  // the temporary is removed with the set
    else file->commit();
  }
  files_.clear();
  streams_.clear();
}

}  // namespace radiant
