// How a render divides each pixel's samples into passes over the whole image. A render that may
// stop early (a time limit, a signal, a noise target, a session watching it) takes the samples in
// passes that double what every pixel holds (1, 2, 4, 8, ...), so a stopped render is the whole
// image at fewer samples. Each pixel still takes its samples in index order and the film's sums
// are exact, so the passes never change a finished render's pixels.
#pragma once

#include <cstdint>

namespace radiant {

// The most samples a pass of adaptive sampling adds once pixels may stop: a pixel overshoots its
// noise target by at most this many.
constexpr uint32_t max_adaptive_pass = 64;

struct PassSchedule {
  uint32_t begin = 0, end = 0;  // the sample indices every pixel takes, [begin, end)
  bool progressive = false;     // passes grow from one sample per pixel; else one pass
  // Adaptive sampling: every pixel takes this many samples before any may stop (0: not adaptive).
  uint32_t min_samples = 0;
};

// The end of the pass after `done` (begin <= done < end): one pass to `end` for a render that
// cannot stop early; otherwise the next power of two of samples taken, no further than
// min_samples while it is ahead, and at most max_adaptive_pass samples a pass past it.
uint32_t next_pass_end(const PassSchedule& schedule, uint32_t done);

// The samples every pixel takes before adaptive sampling may stop it, as Cycles derives them from
// the noise threshold (16 / threshold^0.3: 0.1 -> 32, 0.01 -> 64, 0.001 -> 128) rounded up to a
// power of two so that it ends a pass; `min_spp` > 0 (--min-spp) overrides it. At most `spp`.
uint32_t adaptive_min_samples(float noise_threshold, uint32_t min_spp, uint32_t spp);

}  // namespace radiant
