#include "animation_flags.h"

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
  fps_option = app.add_option("--fps", fps, "Frames per second of --frame")->check(positive_number(1e6));
  app.add_option("--animation", animation, "glTF animation by name or index (default: the first)");
}

void AnimationFlags::finish(LoadOptions& load) const {
  if (*time_option && *frame_option) throw CLI::ValidationError("--time", "give --time or --frame, not both");
  if (*frame_option && !*fps_option) throw CLI::ValidationError("--frame", "needs --fps");
  if (*fps_option && !*frame_option) throw CLI::ValidationError("--fps", "only applies with --frame");
  if (*time_option) load.animation_time = time;
  if (*frame_option) load.animation_time = double(frame) / fps;
  if (!animation.empty() && !load.animation_time) load.animation_time = 0.0;
  load.animation = animation;
}

}  // namespace radiant::cli
