// --time, --frame with --fps, --frames, --animation, --same-noise and --shutter: the moments of a glTF
// animation `render` loads, and the seed of each frame.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>

#include "frame_range.h"
#include "load_scene.h"

namespace radiant::cli {

// Frames per second of --frames when --fps is not given (Blender's default).
constexpr double default_frames_fps = 24;

struct AnimationFlags {
  double time = 0, fps = 0;
  long long frame = 0;
  std::string animation, frames_text, shutter_text;
  bool same_noise = false;
  std::optional<FrameRange> frames;  // set by finish() for --frames
  CLI::Option *time_option = nullptr, *frame_option = nullptr, *fps_option = nullptr, *frames_option = nullptr,
              *same_noise_option = nullptr, *shutter_option = nullptr;
  void bind(CLI::App& app);
  // Sets load.animation_time (seconds: --time, or --frame / --fps), load.animation,
  // load.shutter (--shutter's frames at --fps, default 24) and `frames`; throws
  // CLI::ValidationError when the flags do not go together.
  void finish(LoadOptions& load);
  // --shutter's OPEN:CLOSE in frames as seconds from the rendered time.
  LoadOptions::Shutter parse_shutter(const std::string& text);
  // The time of frame `number` in seconds.
  double frame_time(long long number) const { return double(number) / fps; }
  // The seed frame `number` renders with (frame_seed, or `seed` itself with --same-noise).
  uint32_t seed_of_frame(uint32_t seed, long long number) const { return same_noise ? seed : frame_seed(seed, number); }
};

}  // namespace radiant::cli
