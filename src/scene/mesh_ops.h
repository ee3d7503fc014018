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
// Gives every triangle its own three vertices (every attribute copied), so that vertex normals
// generated afterwards are the face normals: flat shading where a format asks for it.
void unweld_triangles(MeshDesc& mesh);
// Per-vertex tangents from texcoords0 (needed by normal maps when the file has none).
void generate_tangents(MeshDesc& mesh);

}  // namespace radiant
