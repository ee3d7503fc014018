// Mesh repairs and derived attributes shared by the loaders.
#pragma once

#include <cstddef>

#include "scene/scene_desc.h"

namespace radiant {

// Removes triangles with repeated indices or zero area; returns how many were removed.
size_t drop_degenerate_triangles(MeshDesc& mesh);
// Area-weighted vertex normals from the triangles (replaces `mesh.normals`).
void generate_normals(MeshDesc& mesh);
// Replaces zero-length or non-finite normals with generated ones; returns how many were bad.
size_t repair_normals(MeshDesc& mesh);
// Flat shading where a format asks for it (glTF without NORMAL, OBJ without vn outside smoothing
// groups): no vertex normals or tangents, so every hit takes its triangle's own normal. A
// normal-mapped mesh needs vertex normals for its tangents: its triangles then get vertices of
// their own and the face normals as vertex normals.
void shade_flat(MeshDesc& mesh, bool normal_mapped);
// Per-vertex tangents from texcoords0 (needed by normal maps when the file has none).
void generate_tangents(MeshDesc& mesh);

}  // namespace radiant
