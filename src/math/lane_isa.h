// Which instruction set a loop over SIMD lanes runs with. radiant's lane loops (the Sobol lanes,
// the cosine warp, the surface lanes) are plain loops GCC vectorises, compiled once for the x86-64 baseline (SSE2)
// and once for AVX2, and picked when they run (AVX2 where the CPU has it). Every choice gives the same bits, integer
// arithmetic and float arithmetic without fused multiply-adds alike (neither target has FMA),
// so shards rendered on machines with and without AVX2 still merge to one image; the tests run
// each choice the CPU has and compare.
#pragma once

namespace radiant {

enum class LaneIsa { best, baseline, avx2 };

// Whether this CPU runs `isa` (best and baseline always).
inline bool lane_isa_available(LaneIsa isa) { return isa != LaneIsa::avx2 || __builtin_cpu_supports("avx2"); }

// The instruction set `isa` asks for, as this CPU can run it: best is AVX2 where the CPU has it.
inline LaneIsa resolve_lane_isa(LaneIsa isa) {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return isa != LaneIsa::baseline && avx2 ? LaneIsa::avx2 : LaneIsa::baseline;
}

}  // namespace radiant
