// A file written beside its target and renamed onto it only when complete, so that the target
// is never left half-written and never replaced by a failed write.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace radiant {

// Created exclusively (O_CREAT | O_EXCL | O_NOFOLLOW: a planted file or symlink is never opened)
// in the target's folder, under a hidden name with an unpredictable part that keeps the target's
// extension, which names the format: out.png → .out.tmp-Xq3v9Tb0kLmZ.png. Mode 0666 & ~umask.
// Every write is checked, and so are fsync and close. Removed unless committed, also by the
// signal handler (temporary_registry.h). Errors throw std::runtime_error naming the target:
// "cannot write 'out.png': No space left on device".
// An existing file it replaces keeps its permission bits (and, when radiant runs as root, its
// owner), as a file rewritten in place would.
class TemporaryFile {
 public:
  // `destination` is the file renamed onto, when it is not `target` itself (the file a symlink
  // leads to); `target` is the name messages use.
  explicit TemporaryFile(std::string target, std::string destination = {});
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  const std::string& target() const { return target_; }
  const std::string& path() const { return path_; }
  // The open file, for writers that take a descriptor; -1 after finish().
  int descriptor() const { return descriptor_; }

  void write(const void* data, size_t size);
  void write(const std::string& text) { write(text.data(), text.size()); }
  // Overwrites bytes already written, at `offset` from the start (a table of offsets that is
  // known only after what it points to).
  void write_at(uint64_t offset, const void* data, size_t size);
  // Inserts bytes at `offset`, moving what follows later (a header line added to a file another
  // writer made), in chunks: no copy of the file is held.
  void insert_at(uint64_t offset, const void* data, size_t size);
  // Reads up to `size` bytes at `offset`; returns how many there were.
  size_t read_at(uint64_t offset, void* data, size_t size) const;
  // Flushes to the disk and closes. Idempotent.
  void finish();
  // finish(), then renames onto the destination.
  void commit();
  // An error about this file, in the one form every writer uses.
  [[noreturn]] void fail(const std::string& reason) const;

 private:
  std::string target_, destination_, path_;
  int descriptor_ = -1;
  int slot_ = -1;  // in the registry while the file exists under path_
};

}  // namespace radiant
