// The temporaries that exist right now, in a fixed table that a signal handler can walk: when a
// signal aborts radiant, every one is unlinked with async-signal-safe calls only.
#pragma once

#include <string>

namespace radiant {

// Records `path`; returns its slot. Throws std::runtime_error when the table is full or the path
// too long for it.
int register_temporary(const std::string& path);

// Forgets a slot, once its file has been renamed into place or removed.
void unregister_temporary(int slot);

// Unlinks every registered path. Async-signal-safe: meant for signal handlers.
void remove_registered_temporaries() noexcept;

}  // namespace radiant
