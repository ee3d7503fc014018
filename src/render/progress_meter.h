// A render's progress on stderr, updated from the render threads as tiles finish. On a terminal
// (ProgressStyle::bar) one line is redrawn a few times a second, "rendering  42%  ETA 12.3s",
// and erased at the end. In a log (ProgressStyle::lines: Slurm, CI, nohup) a whole line is
// printed at every tenth of the work and at least every 30 seconds, with the samples per pixel
// the whole image has reached, the time elapsed and the estimate. The estimate knows the time
// limit (it never promises more than the time left) and adaptive sampling (the work left is
// re-estimated after each pass from the pixels still active).
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <optional>

#include "render/render_options.h"

namespace radiant {

class ProgressMeter {
 public:
  using Clock = std::chrono::steady_clock;
  // `total_work` in pixel samples; `spp`: the samples per pixel asked for.
  ProgressMeter(ProgressStyle style, uint64_t total_work, uint32_t spp, std::optional<Clock::time_point> deadline);
  ~ProgressMeter();  // erases the bar
  ProgressMeter(const ProgressMeter&) = delete;
  ProgressMeter& operator=(const ProgressMeter&) = delete;

  // From any render thread: `work` more pixel samples are done.
  void add(uint64_t work);
  // Between passes: the work still to do changed (adaptive sampling stopped some pixels).
  void set_remaining(uint64_t remaining_work);
  // Between passes: every pixel holds at least `samples` samples (all of them: the last line).
  void set_samples_reached(uint32_t samples);

 private:
  struct Estimate {
    double elapsed, fraction, eta;  // eta < 0: none yet
  };
  Estimate estimate(Clock::time_point now) const;
  void print_bar(const Estimate& e);
  void print_line(const Estimate& e);

  ProgressStyle style_;
  Clock::time_point start_;
  uint32_t spp_;
  std::optional<Clock::time_point> deadline_;
  std::atomic<uint64_t> done_{0}, total_;
  std::atomic<uint32_t> samples_reached_{0};
  std::atomic<int64_t> next_print_ns_{0};  // since start_; the thread that moves it prints
  std::atomic<int> next_tenth_{1};         // lines: the tenth of the work whose crossing prints
  std::mutex line_mutex_;                  // lines: one thread prints at a time
};

}  // namespace radiant
