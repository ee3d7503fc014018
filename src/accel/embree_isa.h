// Which instruction set Embree traces with on this machine. Its kernels for SSE, AVX, AVX2 and
// AVX-512 may round an intersection differently, so shards rendered on different ISAs are not
// merged (docs/distributed.md).
#pragma once

#include <string>

namespace radiant {

// "avx512", "avx2", "avx", "sse4.2" or "sse2": the best ISA the CPU has, which Debian's Embree
// (built for all of them) selects.
std::string embree_isa_name();

}  // namespace radiant
