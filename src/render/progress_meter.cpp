#include "render/progress_meter.h"

#include <algorithm>
#include <cstdio>

namespace radiant {

namespace {
constexpr int64_t print_interval_ns = 250'000'000;  // four updates a second
}

ProgressMeter::ProgressMeter(bool enabled, uint64_t total_work, std::optional<Clock::time_point> deadline)
    : enabled_(enabled), start_(Clock::now()), deadline_(deadline), total_(std::max<uint64_t>(1, total_work)) {
  if (!enabled_) return;
  std::fprintf(stderr, "\rrendering   0%%%14s", "");  // the load is over
  std::fflush(stderr);
}

ProgressMeter::~ProgressMeter() {
  if (!enabled_) return;
  std::fprintf(stderr, "\r%40s\r", "");
  std::fflush(stderr);
}

void ProgressMeter::add(uint64_t work) {
  if (!enabled_) return;
  done_.fetch_add(work, std::memory_order_relaxed);
  Clock::time_point now = Clock::now();
  int64_t elapsed = std::chrono::duration_cast<std::chrono::nanoseconds>(now - start_).count();
  int64_t due = next_print_ns_.load(std::memory_order_relaxed);
  // One thread wins the update; the others go back to rendering.
  if (elapsed >= due && next_print_ns_.compare_exchange_strong(due, elapsed + print_interval_ns)) print(now);
}

void ProgressMeter::set_remaining(uint64_t remaining_work) {
  total_.store(std::max<uint64_t>(1, done_.load() + remaining_work));
}

void ProgressMeter::print(Clock::time_point now) {
  double elapsed = std::chrono::duration<double>(now - start_).count();
  double fraction = std::min(1.0, double(done_.load(std::memory_order_relaxed)) / double(total_.load()));
  double eta = fraction > 0 ? elapsed * (1 - fraction) / fraction : -1;
  if (deadline_) {
    double left = std::max(0.0, std::chrono::duration<double>(*deadline_ - now).count());
    eta = eta < 0 ? left : std::min(eta, left);
    // The time limit ends the render at 100% of what it will do.
    if (elapsed + left > 0) fraction = std::max(fraction, elapsed / (elapsed + left));
  }
  if (eta < 0) std::fprintf(stderr, "\rrendering %3d%%%14s", int(fraction * 100), "");
  else std::fprintf(stderr, "\rrendering %3d%%  ETA %5.1fs ", int(fraction * 100), eta);
  std::fflush(stderr);
}

}  // namespace radiant
