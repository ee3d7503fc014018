#include "output/temporary_registry.h"

#include <limits.h>
#include <unistd.h>

#include <atomic>
#include <cstring>
#include <stdexcept>

namespace radiant {

namespace {

enum SlotState : int { slot_free, slot_filling, slot_ready };

struct Slot {
  std::atomic<int> state{slot_free};
  char path[PATH_MAX];
};

// A command writes a handful of files at once (render: image and stats; converge: three).
constexpr int slot_count = 32;
Slot slots[slot_count];

static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads the slots' states");

}  // namespace

int register_temporary(const std::string& path) {
  if (path.size() >= PATH_MAX) throw std::runtime_error("path too long: " + path);
  for (int i = 0; i < slot_count; ++i) {
    int expected = slot_free;
    if (!slots[i].state.compare_exchange_strong(expected, slot_filling)) continue;
    std::memcpy(slots[i].path, path.c_str(), path.size() + 1);
    slots[i].state.store(slot_ready, std::memory_order_release);
    return i;
  }
  throw std::runtime_error("more than " + std::to_string(slot_count) + " temporary files at once");
}

void unregister_temporary(int slot) { slots[slot].state.store(slot_free, std::memory_order_release); }

void remove_registered_temporaries() noexcept {
  for (Slot& slot : slots)
    if (slot.state.load(std::memory_order_acquire) == slot_ready) unlink(slot.path);
}

}  // namespace radiant
