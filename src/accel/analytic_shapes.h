// Ray intersection with spheres, infinite planes, capped cylinders and infinite tubes.
// Computed in double relative to the shape's own centre so that grazing rays and scenes far
// from the origin keep their precision; radiant hands these to Embree as user geometry.
#pragma once

#include "accel/ray.h"
#include "scene/scene_desc.h"

namespace radiant {

struct ShapeHit {
  float t = 0;
  vec3 normal;  // unit, outward (the plane's own normal for planes)
  vec2 uv;      // surface parameterisation (for textures)
};

// Nearest hit with t in (tmin, tmax); false when there is none.
bool intersect_shape(const ShapeDesc& shape, const Ray& ray, float tmin, ShapeHit& hit);

// World-space bounds; infinite shapes get finite bounds of +-`infinite_extent`.
void shape_bounds(const ShapeDesc& shape, float infinite_extent, vec3& lower, vec3& upper);

// Reprojects an approximate hit point (with the hit's normal) onto the shape and bounds the
// rounding error of the result.
void refine_shape_point(const ShapeDesc& shape, vec3 approximate, vec3 normal, vec3& point, vec3& error);

}  // namespace radiant
