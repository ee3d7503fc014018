#include "render/pass_schedule.h"

#include <algorithm>
#include <cmath>

namespace radiant {

namespace {

uint32_t power_of_two_at_least(uint32_t n) {
  uint32_t p = 1;
  while (p < n && p < (1u << 31)) p <<= 1;
  return p;
}

}  // namespace

uint32_t next_pass_end(const PassSchedule& schedule, uint32_t done) {
  if (!schedule.progressive) return schedule.end;
  uint32_t taken = done - schedule.begin;
  uint32_t pass = std::max<uint32_t>(1, taken);  // doubles what each pixel holds
  if (schedule.min_samples > 0 && taken >= schedule.min_samples) pass = std::min(pass, max_adaptive_pass);
  uint64_t end = uint64_t(done) + pass;
  if (taken < schedule.min_samples) end = std::min<uint64_t>(end, schedule.begin + uint64_t(schedule.min_samples));
  return uint32_t(std::min<uint64_t>(end, schedule.end));
}

uint32_t adaptive_min_samples(float noise_threshold, uint32_t min_spp, uint32_t spp) {
  uint32_t samples = min_spp;
  if (samples == 0) {
    double cycles = std::ceil(16.0 / std::pow(double(noise_threshold), 0.3));
    samples = power_of_two_at_least(uint32_t(std::clamp(cycles, 4.0, double(1u << 24))));
  }
  return std::min(samples, spp);
}

}  // namespace radiant
