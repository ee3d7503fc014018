// Morph targets and skinning applied to one primitive's vertices, before its triangles and
// shading frames are built (glTF 2.0 sections 3.7.2.2 and 3.7.3): the posed mesh a node shows.
#pragma once

#include <vector>

#include "gltf/gltf_context.h"

namespace radiant {

// How one node deforms a mesh: its morph target weights (node `weights`, else the mesh's) and,
// when skinned, each joint's world transform times its inverse bind matrix.
struct MeshPose {
  std::vector<double> weights;
  std::vector<mat4> joint_matrices;  // empty: not skinned
  bool deforms() const;              // some weight is not 0, or skinned
};

// Adds the weighted deltas of `primitive`'s targets (POSITION, NORMAL, TANGENT) to the mesh's
// attributes (read from the same primitive, in accessor order); normals are renormalized.
void apply_morph_targets(const GltfContext& context, const tinygltf::Primitive& primitive,
                         const std::vector<double>& weights, MeshDesc& mesh, const std::string& where);

// Replaces positions, normals and tangents by their skinned values: each vertex moves by the
// sum over its influences (JOINTS_n / WEIGHTS_n, every set) of weight x joint matrix, the
// weights normalized to sum 1. Positions end in world space.
void apply_skin(const GltfContext& context, const tinygltf::Primitive& primitive,
                const std::vector<mat4>& joint_matrices, MeshDesc& mesh, const std::string& where);

}  // namespace radiant
