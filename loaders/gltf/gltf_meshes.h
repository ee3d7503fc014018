// glTF meshes to SceneDesc meshes: one MeshDesc per triangle primitive, stored once however many
// nodes use the mesh.
#pragma once

#include "gltf/gltf_context.h"

namespace radiant {

// Fills context.mesh_parts and appends the meshes; needs the materials converted first.
void convert_meshes(GltfContext& context);

// The MeshDesc `mesh` with its triangle winding reversed, made once, for mirroring instances.
int mirrored_mesh(GltfContext& context, int mesh);

}  // namespace radiant
