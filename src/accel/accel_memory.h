// What building the Embree accelerator of a scene costs in memory, estimated before it is built
// so that the memory budget can refuse first. The costs were measured (peak resident memory of
// build_scene_accel with Embree 3.13); docs/gltf-obj.md lists them.
#pragma once

#include <cstdint>

#include "scene/scene_desc.h"

namespace radiant {

// Each placed mesh once (its BVH, Embree's copies of its vertices and indices, the world-space
// positions of a mesh placed on the top level), every instance, and the analytic shapes.
uint64_t accel_build_bytes(const SceneDesc& scene);

}  // namespace radiant
