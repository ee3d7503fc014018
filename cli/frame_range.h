// Many frames of one animation: the range `--frames A-B` names, each frame's output name (a run
// of '#' in -o becomes its zero-padded number) and each frame's seed.
#pragma once

#include <cstdint>
#include <string>

namespace radiant::cli {

struct FrameRange {
  long long first = 0, last = 0;  // inclusive
};

// "A-B" with 0 <= A <= B <= 10^9, or one frame "A". Throws CLI::ValidationError naming `flag`.
FrameRange parse_frame_range(const std::string& flag, const std::string& text);

// True when `pattern` has a run of '#' for the frame number.
bool has_frame_placeholder(const std::string& pattern);

// `pattern` with its last run of '#' replaced by `frame`, zero-padded to the run's length
// ("out/f-####.png", 7 -> "out/f-0007.png"; a longer number is written whole), as Blender does.
std::string frame_path(const std::string& pattern, long long frame);

// The seed frame `frame` renders with: hash_combine(mix_bits(seed), frame) (src/sampling/hash.h),
// so that the noise pattern changes from frame to frame, and one frame's image is the same
// whether it is rendered alone (--frame) or among others (--frames).
uint32_t frame_seed(uint32_t seed, long long frame);

}  // namespace radiant::cli
