// One memory cap for a whole command (`--max-memory`): loading and rendering charge every large
// allocation here before making it, so that a file declaring gigabytes is refused with one line
// saying what needed how much, instead of exhausting the machine.
#pragma once

#include <cstdint>
#include <set>
#include <stdexcept>
#include <string>

namespace radiant {

// A charge the budget refused; what() is one line ("...: 1.9 GiB needed, over the memory limit
// of 100 MiB (--max-memory)").
struct MemoryLimitError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class MemoryBudget {
 public:
  // `limit_source` says where the limit comes from, for messages ("--max-memory").
  explicit MemoryBudget(uint64_t limit_bytes, std::string limit_source = "--max-memory");

  // Adds `bytes` for `what` (a file and a place: "model.gltf: meshes[0]"), or, when that would
  // pass the limit, charges nothing and throws MemoryLimitError.
  void charge(uint64_t bytes, const std::string& what);
  // Charges `bytes` for `key` the first time only, like charge(): for what stays for the rest
  // of the process once made (a library loaded on first use).
  void charge_once(const std::string& key, uint64_t bytes, const std::string& what);
  // Charges `bytes` and returns true, or returns false and charges nothing.
  bool try_charge(uint64_t bytes);
  // The one-line refusal of `bytes` more for `what`.
  std::string refusal(uint64_t bytes, const std::string& what) const;
  // Gives back bytes charged earlier (never below zero).
  void release(uint64_t bytes);

  uint64_t used() const { return used_; }
  uint64_t limit() const { return limit_; }
  const std::string& limit_source() const { return limit_source_; }

 private:
  uint64_t limit_;
  uint64_t used_ = 0;
  std::string limit_source_;
  std::set<std::string> charged_once_;
};

// Bytes held against a budget for as long as this object lives (a film, an accelerator). A null
// budget charges nothing: callers without a cap (unit tests, benchmarks) pass none.
class MemoryCharge {
 public:
  MemoryCharge() = default;
  // Throws MemoryLimitError when the budget refuses.
  MemoryCharge(MemoryBudget* budget, uint64_t bytes, const std::string& what);
  // Takes over `bytes` already charged to `budget` (by a loader's raw charges), to be given back
  // by this object.
  static MemoryCharge adopt(MemoryBudget* budget, uint64_t bytes);
  MemoryCharge(MemoryCharge&& other) noexcept;
  MemoryCharge& operator=(MemoryCharge&& other) noexcept;
  MemoryCharge(const MemoryCharge&) = delete;
  MemoryCharge& operator=(const MemoryCharge&) = delete;
  ~MemoryCharge();

  uint64_t bytes() const { return bytes_; }

 private:
  MemoryBudget* budget_ = nullptr;
  uint64_t bytes_ = 0;
};

// The limit when --max-memory is not given: a quarter of physical memory.
uint64_t default_memory_limit();
// How messages name that default.
inline constexpr const char* default_memory_limit_source = "a quarter of RAM; raise it with --max-memory";

// `bytes` for people: "512 bytes", "3.5 KiB", "100 MiB", "1.9 GiB" (three significant digits).
std::string format_bytes(uint64_t bytes);

// a * b and a + b, saturating at the largest uint64_t: a size computed from hostile numbers must not wrap
// around to something small enough to pass.
uint64_t saturating_multiply(uint64_t a, uint64_t b);
uint64_t saturating_add(uint64_t a, uint64_t b);

}  // namespace radiant
