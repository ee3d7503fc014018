#include "accel/accel_memory.h"

#include <vector>

#include "memory/memory_budget.h"

namespace radiant {

namespace {

// Measured: 111 bytes a triangle for a mesh of two million (BVH, Embree's index copy and build
// temporaries), about 500 bytes an instance; a vertex is Embree's padded copy and radiant's
// placed one.
constexpr uint64_t triangle_cost = 160, vertex_cost = 32, instance_cost = 512, shape_cost = 256;
// A stroke's primitive (segment or point) as Embree holds it: its float4 vertex, index and BVH
// share, and the radii worked out for the view.
constexpr uint64_t stroke_primitive_cost = 160;

}  // namespace

uint64_t accel_build_bytes(const SceneDesc& scene) {
  std::vector<char> placed(scene.meshes.size(), 0);
  uint64_t bytes = 0;
  for (const InstanceDesc& instance : scene.instances) {
    // A moving instance holds a transform per time step; a deforming mesh a vertex copy per step.
    bytes = saturating_add(bytes, instance_cost + instance.motion.size() * sizeof(mat4));
    if (instance.mesh < 0 || size_t(instance.mesh) >= scene.meshes.size() || placed[size_t(instance.mesh)]) continue;
    placed[size_t(instance.mesh)] = 1;
    const MeshDesc& mesh = scene.meshes[size_t(instance.mesh)];
    bytes = saturating_add(bytes, mesh.triangle_count() * triangle_cost + mesh.positions.size() * vertex_cost);
    bytes = saturating_add(bytes, saturating_multiply(mesh.motion_positions.size(), mesh.positions.size() * vertex_cost));
  }
  for (const StrokeDesc& stroke : scene.strokes)
    bytes = saturating_add(bytes, saturating_add(stroke.primitive_count(), stroke.positions.size()) * stroke_primitive_cost);
  return saturating_add(bytes, scene.shapes.size() * shape_cost);
}

}  // namespace radiant
