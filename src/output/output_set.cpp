#include "output/output_set.h"

namespace radiant {

TemporaryFile& OutputSet::create(const std::string& target) {
  files_.push_back(std::make_unique<TemporaryFile>(target));
  return *files_.back();
}

void OutputSet::remove(const TemporaryFile& file) {
  std::erase_if(files_, [&](const std::unique_ptr<TemporaryFile>& f) { return f.get() == &file; });
}

void OutputSet::commit() {
  for (auto& file : files_) file->finish();
  for (auto& file : files_) file->commit();
  files_.clear();
}

}  // namespace radiant
