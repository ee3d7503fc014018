// Which instruction set Embree traces with. Its SSE, AVX, AVX2 and AVX-512 kernels may round an
// intersection differently, so shards rendered with different ones are not merged
// (docs/distributed.md, "What the ISA check guarantees").
//
// Embree 3 has no device property that names the ISA it selected (rtcGetDeviceProperty answers
// the version, whether 4-, 8- and 16-wide packets are native, and which features were compiled
// in), and inferring it from CPU flags means copying Embree's own feature masks, which a CPU
// that lacks one flag of them (a VM hiding RDRAND or BMI2) silently breaks. So radiant does not
// infer: it creates every device with `isa=NAME` (a documented rtcNewDevice option), where NAME
// is the best ISA a device accepts on this CPU; Embree refuses to create a device for an ISA the
// CPU lacks, and then uses exactly that ISA's kernels.
#pragma once

#include <functional>
#include <string>

namespace radiant {

// "avx512", "avx2", "avx", "sse4.2" or "sse2": the ISA of every Embree device radiant creates.
const std::string& embree_isa_name();

// "avx2, Embree 3.13.5": the ISA and the Embree library's version (asked of a device), which
// together decide how intersections round. A shard records it (radiant:isa).
std::string embree_kernels_name();

// The configuration of every Embree device radiant creates: the ISA above, and the frequency
// level Embree would otherwise pick by CPU model (it keeps 8-wide BVHs off on Skylake Xeons), so
// that the BVH's layout depends on the ISA alone.
std::string embree_device_config();

// The best of avx512, avx2, avx, sse4.2 and sse2 for which `accepts(isa)` is true, or "" when
// none is. embree_isa_name() asks it of Embree.
std::string best_accepted_isa(const std::function<bool(const std::string& isa)>& accepts);

}  // namespace radiant
