// A scene of a few analytic shapes and no meshes (the classic ray-tracing scene: spheres on a
// plane) is traced by testing every shape in turn, without Embree: for so few shapes, Embree's
// traversal and its user-geometry callbacks cost more than the intersections they avoid
// (measured in docs/performance.md). Spheres are first culled four at a time in float; the
// shapes left are tested by the same exact code, with the same t range, as Embree's callbacks
// use, so both paths find the same hits (only which of two shapes hit at exactly the same
// distance can differ).
#pragma once

#include <cstddef>
#include <vector>

#include "accel/analytic_shapes.h"
#include "accel/hit_id.h"
#include "accel/ray.h"
#include "scene/scene_desc.h"

namespace radiant {

// The most shapes traced directly; beyond it Embree's BVH is cheaper.
constexpr size_t max_shapes_traced_directly = 16;

struct DirectShapes {
  using float4 = float __attribute__((vector_size(16)));
  struct SphereGroup {
    float4 x, y, z;
    float4 reach;   // the radius and the part of the culling margin that depends on the sphere
    int shape[4];   // the index of each lane's shape in SceneDesc::shapes
    int lanes = 0;  // bit k set when lane k holds a sphere (the last group may have empty lanes)
  };
  bool enabled = false;
  std::vector<SphereGroup> spheres;
  std::vector<int> others;  // every shape that is not a sphere, tested without culling
};

// The direct tracing of `scene`'s shapes; disabled when it has meshes or more shapes than the limit.
DirectShapes direct_shapes_of(const SceneDesc& scene);

// A shape hit (at t) well inside the traceable range (SceneAccel::max_ray_coordinate): rays spawned
// there, offset origins and shadow rays to any light included, stay traceable. Only infinite
// planes and tubes can be hit beyond it, so this cuts them off at a distance no view resolves.
bool shape_hit_in_range(float max_ray_coordinate, const Ray& ray, double t);

// The nearest of `shapes` hit with t in (0, ray.tmax), as intersect_nearest reports it.
HitId nearest_shape_directly(const DirectShapes& direct, const std::vector<ShapeDesc>& shapes, float max_ray_coordinate,
                             const Ray& ray);
// Whether any of `shapes` is hit with t in (0, ray.tmax).
bool shapes_block_directly(const DirectShapes& direct, const std::vector<ShapeDesc>& shapes, float max_ray_coordinate,
                           const Ray& ray);

}  // namespace radiant
