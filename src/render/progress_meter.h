// The progress line of a render on a terminal: "rendering  42%  ETA 12.3s", updated from the
// render threads as tiles finish, a few times a second, and erased at the end. The estimate
// knows the time limit (it never promises more than the time left) and adaptive sampling (the
// work left is re-estimated after each pass from the pixels still active).
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <optional>

namespace radiant {

class ProgressMeter {
 public:
  using Clock = std::chrono::steady_clock;
  // `enabled` false: prints nothing. `total_work` in pixel samples.
  ProgressMeter(bool enabled, uint64_t total_work, std::optional<Clock::time_point> deadline);
  ~ProgressMeter();  // erases the line
  ProgressMeter(const ProgressMeter&) = delete;
  ProgressMeter& operator=(const ProgressMeter&) = delete;

  // From any render thread: `work` more pixel samples are done.
  void add(uint64_t work);
  // Between passes: the work still to do changed (adaptive sampling stopped some pixels).
  void set_remaining(uint64_t remaining_work);

 private:
  void print(Clock::time_point now);

  bool enabled_;
  Clock::time_point start_;
  std::optional<Clock::time_point> deadline_;
  std::atomic<uint64_t> done_{0}, total_;
  std::atomic<int64_t> next_print_ns_{0};  // since start_; the thread that moves it prints
};

}  // namespace radiant
