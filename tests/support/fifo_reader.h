// The reading end of a FIFO on a thread of its own, collecting everything written into it. The
// reader holds a write end too until finish(), so that it neither sees the end of the data before
// the writer comes nor waits forever when none does (a FIFO replaced by a regular file).
#pragma once

#include <fcntl.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <thread>

namespace radiant::test {

class FifoReader {
 public:
  explicit FifoReader(const std::filesystem::path& fifo)
      : read_end_(open(fifo.c_str(), O_RDONLY | O_NONBLOCK)), own_write_end_(open(fifo.c_str(), O_WRONLY)) {
    fcntl(read_end_, F_SETFL, 0);  // blocking reads from now on
    thread_ = std::thread([this] {
      char buffer[1 << 16];
      for (ssize_t got; (got = read(read_end_, buffer, sizeof buffer)) > 0;) received_.append(buffer, size_t(got));
    });
  }
  ~FifoReader() {
    if (thread_.joinable()) finish();
  }
  // Once the writer is done: everything it wrote.
  std::string finish() {
    close(own_write_end_);
    thread_.join();
    close(read_end_);
    return received_;
  }

 private:
  int read_end_, own_write_end_;
  std::thread thread_;
  std::string received_;
};

}  // namespace radiant::test
