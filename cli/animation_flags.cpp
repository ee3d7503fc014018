#include "animation_flags.h"

#include <cmath>

#include "number_parsing.h"
#include "option_parsing.h"

namespace radiant::cli {

// A frame number or rate of any sign would do for the arithmetic, but a time far beyond any
// key is the last key anyway: the bounds only keep the numbers finite.
constexpr double largest_time = 1e9;

void AnimationFlags::bind(CLI::App& app) {
  time_option = app.add_option("--time", time, "glTF: sample the animation at this time in seconds")
                    ->check(number_in(-largest_time, largest_time));
  frame_option = app.add_option("--frame", frame, "glTF: sample the animation at frame N (with --fps)")
                     ->check(CLI::Range(0LL, 1000000000LL));
  frames_option = app.add_option("--frames", frames_text,
                                 "glTF: render frames A-B in one process; -o holds # for the frame number");
  fps_option = app.add_option("--fps", fps, "Frames per second of --frame (and of --frames, default 24)")
                   ->check(positive_number(1e6));
  app.add_option("--animation", animation, "glTF animation by name or index (default: the first)");
  shutter_option = app.add_option("--shutter", shutter_text,
                                  "glTF: motion blur over OPEN:CLOSE frames around the rendered time (e.g. -0.25:0.25)");
  same_noise_option = app.add_flag("--same-noise", same_noise,
                                   "Every frame with the noise of --seed itself (Cycles: Animated Seed off)");
}

LoadOptions::Shutter AnimationFlags::parse_shutter(const std::string& text) {
  std::vector<std::string> parts = split(text, ':');
  if (parts.size() != 2) throw CLI::ValidationError("--shutter", "expects OPEN:CLOSE in frames, e.g. -0.25:0.25");
  double open = parse_number("--shutter", parts[0]), close = parse_number("--shutter", parts[1]);
  constexpr double largest_shutter = 1e6;  // frames: keeps the times finite
  if (!(open < close) || !(std::abs(open) <= largest_shutter && std::abs(close) <= largest_shutter))
    throw CLI::ValidationError("--shutter", "needs OPEN < CLOSE, in frames (e.g. -0.25:0.25)");
  double frame = 1 / (*fps_option ? fps : default_frames_fps);
  return {open * frame, close * frame};
}

void AnimationFlags::finish(LoadOptions& load) {
  if (int(bool(*time_option)) + int(bool(*frame_option)) + int(bool(*frames_option)) > 1)
    throw CLI::ValidationError("--time", "give one of --time, --frame and --frames");
  if (*frame_option && !*fps_option) throw CLI::ValidationError("--frame", "needs --fps");
  if (*fps_option && !*frame_option && !*frames_option && !*shutter_option)
    throw CLI::ValidationError("--fps", "only applies with --frame, --frames or --shutter");
  if (*same_noise_option && !*frame_option && !*frames_option)
    throw CLI::ValidationError("--same-noise", "only applies with --frame or --frames");
  if (*time_option) load.animation_time = time;
  if (*frame_option) load.animation_time = frame_time(frame);
  if (*frames_option) {
    frames = parse_frame_range("--frames", frames_text);
    if (!*fps_option) fps = default_frames_fps;
    load.animation_time = frame_time(frames->first);
  }
  if (*shutter_option) {
    load.shutter = parse_shutter(shutter_text);
    if (!load.animation_time) load.animation_time = 0.0;
  }
  if (!animation.empty() && !load.animation_time) load.animation_time = 0.0;
  load.animation = animation;
}

}  // namespace radiant::cli
