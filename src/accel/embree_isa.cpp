#include "accel/embree_isa.h"

namespace radiant {

std::string embree_isa_name() {
  // Embree 3's own test for its AVX-512 kernels (SKX): F, DQ, CD, BW and VL together.
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512cd") &&
      __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512vl"))
    return "avx512";
  if (__builtin_cpu_supports("avx2")) return "avx2";
  if (__builtin_cpu_supports("avx")) return "avx";
  if (__builtin_cpu_supports("sse4.2")) return "sse4.2";
  return "sse2";
}

}  // namespace radiant
