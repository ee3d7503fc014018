#include "memory/memory_budget.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <utility>

namespace radiant {

MemoryBudget::MemoryBudget(uint64_t limit_bytes, std::string limit_source)
    : limit_(limit_bytes), limit_source_(std::move(limit_source)) {}

bool MemoryBudget::try_charge(uint64_t bytes) {
  if (bytes > limit_ - used_) return false;  // used_ <= limit_ always holds, so this cannot wrap
  used_ += bytes;
  return true;
}

void MemoryBudget::charge(uint64_t bytes, const std::string& what) {
  if (!try_charge(bytes)) throw MemoryLimitError(refusal(bytes, what));
}

void MemoryBudget::charge_once(const std::string& key, uint64_t bytes, const std::string& what) {
  if (charged_once_.count(key)) return;
  charge(bytes, what);
  charged_once_.insert(key);
}

std::string MemoryBudget::refusal(uint64_t bytes, const std::string& what) const {
  std::string held = used_ > 0 ? " (with " + format_bytes(used_) + " already in use)" : "";
  return what + ": " + format_bytes(bytes) + " needed" + held + ", over the memory limit of " +
         format_bytes(limit_) + " (" + limit_source_ + ")";
}

void MemoryBudget::release(uint64_t bytes) { used_ -= std::min(bytes, used_); }

MemoryCharge::MemoryCharge(MemoryBudget* budget, uint64_t bytes, const std::string& what) {
  if (!budget) return;
  budget->charge(bytes, what);
  budget_ = budget;
  bytes_ = bytes;
}

MemoryCharge MemoryCharge::adopt(MemoryBudget* budget, uint64_t bytes) {
  MemoryCharge charge;
  charge.budget_ = budget;
  charge.bytes_ = budget ? bytes : 0;
  return charge;
}

MemoryCharge::MemoryCharge(MemoryCharge&& other) noexcept
    : budget_(std::exchange(other.budget_, nullptr)), bytes_(std::exchange(other.bytes_, 0)) {}

MemoryCharge& MemoryCharge::operator=(MemoryCharge&& other) noexcept {
  if (this != &other) {
    if (budget_) budget_->release(bytes_);
    budget_ = std::exchange(other.budget_, nullptr);
    bytes_ = std::exchange(other.bytes_, 0);
  }
  return *this;
}

MemoryCharge::~MemoryCharge() {
  if (budget_) budget_->release(bytes_);
}

uint64_t default_memory_limit() {
  long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return uint64_t(4) << 30;
  return uint64_t(pages) * uint64_t(page_size) / 4;
}

std::string format_bytes(uint64_t bytes) {
  if (bytes < 1024) return std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes");
  static const char* units[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  double value = double(bytes) / 1024;
  int unit = 0;
  while (value >= 1024 && unit < 5) value /= 1024, ++unit;
  char text[32];
  std::snprintf(text, sizeof text, value < 10 ? "%.2f %s" : value < 100 ? "%.1f %s" : "%.0f %s", value, units[unit]);
  return text;
}

uint64_t saturating_multiply(uint64_t a, uint64_t b) {
  uint64_t product;
  if (__builtin_mul_overflow(a, b, &product)) return std::numeric_limits<uint64_t>::max();
  return product;
}

uint64_t saturating_add(uint64_t a, uint64_t b) {
  uint64_t sum;
  if (__builtin_add_overflow(a, b, &sum)) return std::numeric_limits<uint64_t>::max();
  return sum;
}

}  // namespace radiant
