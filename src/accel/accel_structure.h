// The Embree acceleration structure of a SceneDesc: a mesh placed once, whose world-space
// vertices are exact floats, sits on the top level (a flat BVH, Embree's fastest); any other
// mesh is one RTCScene shared by its instances; the analytic shapes are one user geometry. A
// scene of a few shapes and no meshes is traced without Embree (accel/direct_shapes.h).
#pragma once

#include <embree3/rtcore.h>

#include <atomic>
#include <cstdint>
#include <vector>

#include "accel/direct_shapes.h"
#include "scene/scene_desc.h"

namespace radiant {

struct SceneAccel {
  const SceneDesc* scene = nullptr;
  RTCDevice device = nullptr;
  RTCScene top = nullptr;
  std::vector<RTCScene> mesh_scenes;  // per mesh; null for meshes on the top level
  std::vector<int> instanced;         // the instances traced through an object space of their own
  std::vector<mat4> instance_inverse;  // world to object, per instance
  std::vector<float> instance_orientation;  // sign of the transform's determinant
  std::vector<char> instance_identity;      // the transform is the identity (hits skip it)
  unsigned shape_geometry = RTC_INVALID_GEOMETRY_ID;
  // Strokes take the geometry IDs from here on, one each (after the instances and the shapes').
  unsigned first_stroke_geometry = RTC_INVALID_GEOMETRY_ID;
  std::vector<float> stroke_max_radius;  // per stroke, for its hits' error bounds
  // What the hit filters (accel/embree_callbacks.h) know of a mesh: its geometries' user data.
  struct MeshFilter {
    const SceneAccel* accel;
    int mesh;
    bool single_sided;  // its material is single-sided: camera rays pass its back faces
  };

  std::vector<MeshFilter> mesh_filters;  // one per mesh
  // Some mesh is single-sided: its scenes take Embree's context filter, which camera rays set.
  bool has_single_sided = false;
  // Every traced ray keeps its origin within this (and its direction within twice this), so that
  // in every instance's object space it stays inside Embree's range (scene/coordinate_range.h).
  // Hits on infinite shapes beyond it are not taken.
  float max_ray_coordinate = 0;
  // Rays refused by that bound (a valid scene casts none): taken as misses, or as blocked
  // shadow rays, and reported in the render's statistics.
  mutable std::atomic<uint64_t> untraceable_rays{0};
  // A few analytic shapes and no meshes: traced without Embree.
  DirectShapes direct_shapes;

  SceneAccel() = default;
  SceneAccel(const SceneAccel&) = delete;
  SceneAccel& operator=(const SceneAccel&) = delete;
  ~SceneAccel();
};

}  // namespace radiant
