// EXT_mesh_gpu_instancing: a node's mesh placed once per element of the extension's TRANSLATION,
// ROTATION and SCALE accessors.
#pragma once

#include <vector>

#include "gltf/gltf_context.h"

namespace radiant {

// The instances' attributes, validated: equal counts, allowed types, finite values, non-zero
// rotations. An absent attribute stays empty (translation 0, rotation identity, scale 1).
struct GpuInstances {
  size_t count = 0;
  std::vector<float> translations;  // 3 per instance
  std::vector<float> rotations;     // 4 per instance (x, y, z, w), non-zero length
  std::vector<float> scales;        // 3 per instance
};

// Reads the extension object `extension` of a node; `where` is its JSON path
// (`nodes[3].extensions.EXT_mesh_gpu_instancing`). Accessor reads are charged to the budget.
GpuInstances read_gpu_instances(const GltfContext& context, const tinygltf::Value& extension, const std::string& where);

// Instance i's transform relative to its node: T * R * S.
mat4 gpu_instance_transform(const GpuInstances& instances, size_t i);

}  // namespace radiant
