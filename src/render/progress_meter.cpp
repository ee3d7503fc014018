#include "render/progress_meter.h"

#include <algorithm>
#include <cstdio>

namespace radiant {

namespace {
constexpr int64_t bar_interval_ns = 250'000'000;      // four updates a second
constexpr int64_t line_interval_ns = 30'000'000'000;  // a log hears at least this often
}  // namespace

ProgressMeter::ProgressMeter(ProgressStyle style, uint64_t total_work, uint32_t spp,
                             std::optional<Clock::time_point> deadline)
    : style_(style), start_(Clock::now()), spp_(spp), deadline_(deadline), total_(std::max<uint64_t>(1, total_work)) {
  if (style_ == ProgressStyle::lines) next_print_ns_ = line_interval_ns;
  if (style_ != ProgressStyle::bar) return;
  std::fprintf(stderr, "\rrendering   0%%%14s", "");  // the load is over
  std::fflush(stderr);
}

ProgressMeter::~ProgressMeter() {
  if (style_ != ProgressStyle::bar) return;
  std::fprintf(stderr, "\r%40s\r", "");
  std::fflush(stderr);
}

void ProgressMeter::add(uint64_t work) {
  if (style_ == ProgressStyle::none) return;
  done_.fetch_add(work, std::memory_order_relaxed);
  Clock::time_point now = Clock::now();
  int64_t elapsed = std::chrono::duration_cast<std::chrono::nanoseconds>(now - start_).count();
  int64_t due = next_print_ns_.load(std::memory_order_relaxed);
  if (style_ == ProgressStyle::bar) {
    // One thread wins the update; the others go back to rendering.
    if (elapsed >= due && next_print_ns_.compare_exchange_strong(due, elapsed + bar_interval_ns)) print_bar(estimate(now));
    return;
  }
  Estimate e = estimate(now);
  int tenth = next_tenth_.load(std::memory_order_relaxed);
  // The last tenth is printed when the last pass ends (set_samples_reached), with its samples.
  if (elapsed < due && (e.fraction * 10 < tenth || e.fraction >= 1)) return;
  std::unique_lock lock(line_mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;  // another thread is printing this very update
  if (elapsed < next_print_ns_.load() && (e.fraction * 10 < next_tenth_.load() || e.fraction >= 1)) return;
  next_tenth_ = std::min(10, int(e.fraction * 10) + 1);
  next_print_ns_ = elapsed + line_interval_ns;
  print_line(e);
}

void ProgressMeter::set_remaining(uint64_t remaining_work) {
  total_.store(std::max<uint64_t>(1, done_.load() + remaining_work));
}

void ProgressMeter::set_samples_reached(uint32_t samples) {
  samples_reached_.store(samples);
  if (style_ == ProgressStyle::lines && samples >= spp_) {
    Estimate e = estimate(Clock::now());
    e.fraction = 1, e.eta = 0;
    std::lock_guard lock(line_mutex_);
    print_line(e);
  }
}

ProgressMeter::Estimate ProgressMeter::estimate(Clock::time_point now) const {
  Estimate e;
  e.elapsed = std::chrono::duration<double>(now - start_).count();
  e.fraction = std::min(1.0, double(done_.load(std::memory_order_relaxed)) / double(total_.load()));
  e.eta = e.fraction > 0 ? e.elapsed * (1 - e.fraction) / e.fraction : -1;
  if (deadline_) {
    double left = std::max(0.0, std::chrono::duration<double>(*deadline_ - now).count());
    e.eta = e.eta < 0 ? left : std::min(e.eta, left);
    // The time limit ends the render at 100% of what it will do.
    if (e.elapsed + left > 0) e.fraction = std::max(e.fraction, e.elapsed / (e.elapsed + left));
  }
  return e;
}

void ProgressMeter::print_bar(const Estimate& e) {
  if (e.eta < 0) std::fprintf(stderr, "\rrendering %3d%%%14s", int(e.fraction * 100), "");
  else std::fprintf(stderr, "\rrendering %3d%%  ETA %5.1fs ", int(e.fraction * 100), e.eta);
  std::fflush(stderr);
}

void ProgressMeter::print_line(const Estimate& e) {
  char eta[32] = "unknown";
  if (e.eta >= 0) std::snprintf(eta, sizeof eta, "%.1f s", e.eta);
  std::fprintf(stderr, "radiant: rendering %3d%%, %u of %u spp reached, %.1f s elapsed, ETA %s\n",
               int(e.fraction * 100), samples_reached_.load(), spp_, e.elapsed, eta);
  std::fflush(stderr);
}

}  // namespace radiant
