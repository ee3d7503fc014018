// --time, --frame with --fps, and --animation: the moment of a glTF animation `render` loads.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "load_scene.h"

namespace radiant::cli {

struct AnimationFlags {
  double time = 0, fps = 0;
  long long frame = 0;
  std::string animation;
  CLI::Option *time_option = nullptr, *frame_option = nullptr, *fps_option = nullptr;
  void bind(CLI::App& app);
  // Sets load.animation_time (seconds: --time, or --frame / --fps) and load.animation; throws
  // CLI::ValidationError when the flags do not go together.
  void finish(LoadOptions& load) const;
};

}  // namespace radiant::cli
