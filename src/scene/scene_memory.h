// What a SceneDesc holds in memory, for the memory budget (src/memory/memory_budget.h): the
// loaders charge a mesh before they grow it and the loaded scene once loading is done.
#pragma once

#include <cstdint>

#include "scene/scene_desc.h"

namespace radiant {

// Bytes of one vertex's attributes as `mesh` stores them (the attributes it has).
uint64_t vertex_bytes(const MeshDesc& mesh);
// Bytes of the mesh's arrays (their capacity) and name.
uint64_t mesh_bytes(const MeshDesc& mesh);
// Bytes of one instance and its name.
uint64_t instance_bytes(const InstanceDesc& instance);
// What a StrokeDesc holds: its vertices, colours and segments.
uint64_t stroke_bytes(const StrokeDesc& stroke);
// Bytes of everything the scene holds: meshes, images, materials, instances, names.
uint64_t scene_memory_bytes(const SceneDesc& scene);
// At most what the shading-frame repairs of mesh_ops.h (shade_flat, generate_normals,
// repair_normals, generate_tangents) add to `mesh`, their temporaries included; a normal-mapped
// mesh may give every triangle corner a vertex of its own.
uint64_t shading_frame_bytes(const MeshDesc& mesh, bool normal_mapped);

}  // namespace radiant
