#include "output/temporary_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/random.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "output/temporary_registry.h"

namespace radiant {

namespace fs = std::filesystem;

namespace {

// Twelve characters of 62: about 71 bits nobody can guess.
std::string random_name_part() {
  static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  unsigned char bytes[12];
  size_t got = 0;
  while (got < sizeof bytes) {
    ssize_t n = getrandom(bytes + got, sizeof bytes - got, 0);
    if (n < 0 && errno != EINTR) throw std::runtime_error(std::string("getrandom: ") + std::strerror(errno));
    if (n > 0) got += size_t(n);
  }
  std::string part;
  for (unsigned char b : bytes) part += alphabet[b % 62];
  return part;
}

// Room for the hidden name's additions within a file name's 255 bytes.
constexpr size_t max_stem_bytes = 200;

// The file that replaces `replaced` takes its permission bits (set-id bits dropped) and, for
// root, its owner and group; a new file keeps 0666 & ~umask.
void keep_permissions_of(const std::string& replaced, const std::string& path) {
  struct stat status;
  if (stat(replaced.c_str(), &status) != 0 || !S_ISREG(status.st_mode)) return;
  // Best effort: the bytes matter more than the bits, and a failure leaves the new file's own.
  if (geteuid() == 0) {
    [[maybe_unused]] int owned = chown(path.c_str(), status.st_uid, status.st_gid);
  }
  [[maybe_unused]] int moded = chmod(path.c_str(), status.st_mode & 0777);
}

}  // namespace

TemporaryFile::TemporaryFile(std::string target, std::string destination)
    : target_(std::move(target)), destination_(destination.empty() ? target_ : std::move(destination)) {
  fs::path p(destination_);
  std::string stem = p.stem().string().substr(0, max_stem_bytes);
  // A clash with an existing name (planted or not) is not an error: another name is drawn.
  for (int attempt = 0; attempt < 100 && descriptor_ < 0; ++attempt) {
    path_ = (p.parent_path() / ("." + stem + ".tmp-" + random_name_part() + p.extension().string())).string();
    descriptor_ = open(path_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (descriptor_ < 0 && errno != EEXIST) fail(std::strerror(errno));
  }
  if (descriptor_ < 0) fail("no free temporary name beside it");
  try {
    slot_ = register_temporary(path_);
  } catch (const std::exception& e) {
    close(descriptor_);
    unlink(path_.c_str());
    fail(e.what());
  }
}

TemporaryFile::~TemporaryFile() {
  if (descriptor_ >= 0) close(descriptor_);
  if (slot_ >= 0) {
    unlink(path_.c_str());  // before forgetting it, so that a signal in between still removes it
    unregister_temporary(slot_);
  }
}

void TemporaryFile::write(const void* data, size_t size) {
  if (descriptor_ < 0) fail("written after it was closed");
  const char* bytes = static_cast<const char*>(data);
  while (size > 0) {
    ssize_t written = ::write(descriptor_, bytes, size);
    if (written < 0 && errno == EINTR) continue;
    if (written < 0) fail(std::strerror(errno));
    bytes += written;
    size -= size_t(written);
  }
}

void TemporaryFile::write_at(uint64_t offset, const void* data, size_t size) {
  if (descriptor_ < 0) fail("written after it was closed");
  const char* bytes = static_cast<const char*>(data);
  while (size > 0) {
    ssize_t written = ::pwrite(descriptor_, bytes, size, off_t(offset));
    if (written < 0 && errno == EINTR) continue;
    if (written < 0) fail(std::strerror(errno));
    bytes += written, offset += uint64_t(written);
    size -= size_t(written);
  }
}

size_t TemporaryFile::read_at(uint64_t offset, void* data, size_t size) const {
  if (descriptor_ < 0) fail("read after it was closed");
  size_t done = 0;
  while (done < size) {
    ssize_t got = ::pread(descriptor_, static_cast<char*>(data) + done, size - done, off_t(offset + done));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) fail(std::strerror(errno));
    if (got == 0) break;
    done += size_t(got);
  }
  return done;
}

void TemporaryFile::insert_at(uint64_t offset, const void* data, size_t size) {
  struct stat status;
  if (descriptor_ < 0 || fstat(descriptor_, &status) != 0) fail("cannot find its size");
  uint64_t end = uint64_t(status.st_size);
  if (offset > end) fail("an insertion past its end");
  // From the end backwards, so that no byte is overwritten before it has moved.
  std::vector<char> chunk(1 << 16);
  while (end > offset) {
    size_t length = size_t(std::min<uint64_t>(chunk.size(), end - offset));
    end -= length;
    if (read_at(end, chunk.data(), length) != length) fail("it changed while being written");
    write_at(end + size, chunk.data(), length);
  }
  write_at(offset, data, size);
}

void TemporaryFile::finish() {
  if (descriptor_ < 0) return;
  // fsync reports the errors of writes the kernel had only buffered; close those of some file
  // systems (NFS). Either means the file is not what was written.
  int synced = fsync(descriptor_), sync_error = errno;
  int closed = close(descriptor_), close_error = errno;
  descriptor_ = -1;
  if (synced != 0) fail(std::strerror(sync_error));
  if (closed != 0) fail(std::strerror(close_error));
}

void TemporaryFile::commit() {
  finish();
  keep_permissions_of(destination_, path_);
  if (rename(path_.c_str(), destination_.c_str()) != 0) fail(std::strerror(errno));
  unregister_temporary(slot_);
  slot_ = -1;
}

void TemporaryFile::fail(const std::string& reason) const {
  throw std::runtime_error("cannot write '" + target_ + "': " + reason);
}

}  // namespace radiant
