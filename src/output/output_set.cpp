#include "output/output_set.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace radiant {

namespace {

// Copies a finished temporary to standard output, every write checked.
void copy_to_standard_output(const TemporaryFile& file) {
  std::ifstream in(file.path(), std::ios::binary);
  char buffer[1 << 16];
  while (in) {
    in.read(buffer, sizeof buffer);
    for (std::streamsize done = 0; done < in.gcount();) {
      ssize_t wrote = ::write(STDOUT_FILENO, buffer + done, size_t(in.gcount() - done));
      if (wrote < 0 && errno == EINTR) continue;
      if (wrote <= 0) throw std::runtime_error(std::string("cannot write to standard output: ") + std::strerror(errno));
      done += wrote;
    }
  }
  if (in.bad()) throw std::runtime_error("cannot read back '" + file.path() + "' for standard output");
}

}  // namespace

TemporaryFile& OutputSet::create(const std::string& target) {
  files_.push_back(std::make_unique<TemporaryFile>(target));
  return *files_.back();
}

TemporaryFile& OutputSet::create_standard_output(const std::string& extension) {
  std::filesystem::path folder = std::filesystem::temp_directory_path();
  TemporaryFile& file = create((folder / ("radiant-standard-output." + extension)).string());
  to_standard_output_.push_back(&file);
  return file;
}

void OutputSet::remove(const TemporaryFile& file) {
  std::erase(to_standard_output_, &file);
  std::erase_if(files_, [&](const std::unique_ptr<TemporaryFile>& f) { return f.get() == &file; });
}

void OutputSet::commit() {
  for (auto& file : files_) file->finish();
  for (auto& file : files_) {
    bool piped = std::find(to_standard_output_.begin(), to_standard_output_.end(), file.get()) != to_standard_output_.end();
    if (piped) copy_to_standard_output(*file);  // the temporary is removed with the set
    else file->commit();
  }
  files_.clear();
  to_standard_output_.clear();
}

}  // namespace radiant
