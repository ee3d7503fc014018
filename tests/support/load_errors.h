// The one-line error a load ends in, for tests that check messages.
#pragma once

#include <filesystem>
#include <string>

#include "load_scene.h"
#include "support/test_support.h"

namespace radiant::test {

// The LoadError of loading `file` (inside `dir`), with the folder's path removed, or "no error".
inline std::string load_error(const ScratchDir& dir, const std::filesystem::path& file, const LoadOptions& options = {}) {
  try {
    load_scene(file.string(), options);
  } catch (const LoadError& error) {
    return dir.without_path(error.what());
  }
  return "no error";
}

}  // namespace radiant::test
