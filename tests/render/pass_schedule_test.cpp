// The pass schedule: what each pass of a render that may stop early adds, and the minimum samples
// adaptive sampling takes before a pixel may stop.
#include <doctest/doctest.h>

#include <vector>

#include "render/pass_schedule.h"

using namespace radiant;

namespace {

std::vector<uint32_t> pass_ends(const PassSchedule& schedule) {
  std::vector<uint32_t> ends;
  for (uint32_t done = schedule.begin; done < schedule.end; done = next_pass_end(schedule, done)) {
    ends.push_back(next_pass_end(schedule, done));
    if (ends.size() > 1000) break;
  }
  return ends;
}

}  // namespace

TEST_CASE("pass schedule: one pass for a render that cannot stop, doubling passes for one that can") {
  CHECK(pass_ends({0, 100, false, 0}) == std::vector<uint32_t>{100});
  CHECK(pass_ends({0, 100, true, 0}) == std::vector<uint32_t>{1, 2, 4, 8, 16, 32, 64, 100});
  CHECK(pass_ends({0, 1, true, 0}) == std::vector<uint32_t>{1});
  // A sample range doubles what it holds of its own range.
  CHECK(pass_ends({40, 50, true, 0}) == std::vector<uint32_t>{41, 42, 44, 48, 50});
}

TEST_CASE("pass schedule: adaptive sampling ends a pass at its minimum, then adds at most 64 samples a pass") {
  CHECK(pass_ends({0, 300, true, 64}) == std::vector<uint32_t>{1, 2, 4, 8, 16, 32, 64, 128, 192, 256, 300});
  CHECK(pass_ends({0, 40, true, 24}) == std::vector<uint32_t>{1, 2, 4, 8, 16, 24, 40});
}

TEST_CASE("adaptive minimum samples: Cycles' 16 / threshold^0.3 rounded up to a power of two, or --min-spp") {
  CHECK(adaptive_min_samples(0.1f, 0, 1024) == 32);   // Cycles: 32
  CHECK(adaptive_min_samples(0.05f, 0, 1024) == 64);  // Cycles: 40
  CHECK(adaptive_min_samples(0.01f, 0, 1024) == 64);  // Cycles: 64
  CHECK(adaptive_min_samples(0.001f, 0, 1024) == 128);  // Cycles: 128
  CHECK(adaptive_min_samples(0.9f, 0, 1024) == 32);   // Cycles: 17
  CHECK(adaptive_min_samples(5.0f, 0, 1024) == 16);   // Cycles: 10
  CHECK(adaptive_min_samples(0.05f, 0, 16) == 16);    // never more than the samples asked for
  CHECK(adaptive_min_samples(0.05f, 8, 1024) == 8);   // --min-spp
  CHECK(adaptive_min_samples(0.05f, 2000, 1024) == 1024);
}
