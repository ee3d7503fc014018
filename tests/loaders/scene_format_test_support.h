// Helpers for the .scene loader tests: load from text, capture the error message.
#pragma once

#include <sstream>
#include <string>

#include "scene_format/scene_format_loader.h"

namespace radiant::test {

// Loads `text` as if it were the file "t.scene" in the current folder.
inline SceneDesc load_scene_text(const std::string& text, const LoadOptions& options = {}) {
  std::istringstream in(text);
  return load_scene_format(in, "t.scene", ".", options);
}

// The LoadError message of loading `text`, or "(loaded)" when it loads.
inline std::string scene_text_error(const std::string& text, const LoadOptions& options = {}) {
  try {
    load_scene_text(text, options);
  } catch (const LoadError& error) {
    return error.what();
  }
  return "(loaded)";
}

}  // namespace radiant::test
