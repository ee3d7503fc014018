// glTF meshes to SceneDesc meshes: one MeshDesc per triangle primitive, stored once however many
// nodes use the mesh.
#pragma once

#include "gltf/gltf_context.h"
#include "gltf/gltf_deform.h"

namespace radiant {

// Fills context.mesh_parts and appends the meshes (morphed by each mesh's default `weights`);
// needs the materials converted first.
void convert_meshes(GltfContext& context);

// Appends glTF mesh `mesh` converted again under `pose` (a node's own weights or skin), named
// with `suffix`, and returns its MeshDesc indices (one per triangle primitive); its points and
// lines go to `strokes`, in the mesh's object space.
std::vector<int> convert_mesh(GltfContext& context, size_t mesh, const MeshPose& pose, const std::string& suffix,
                              std::vector<StrokeDesc>& strokes);

// The MeshDesc `mesh` with its triangle winding reversed, made once, for mirroring instances.
int mirrored_mesh(GltfContext& context, int mesh);

}  // namespace radiant
