// Ray intersection with spheres, infinite planes, capped cylinders and infinite tubes.
// Computed in double relative to the shape's own centre so that grazing rays and scenes far
// from the origin keep their precision; radiant hands these to Embree as user geometry.
#pragma once

#include <cstdint>

#include "accel/ray.h"
#include "scene/scene_desc.h"

namespace radiant {

struct ShapeHit {
  float t = 0;
  vec3 normal;  // unit, outward (the plane's own normal for planes)
  vec2 uv;      // surface parameterisation (for textures)
};

// Which part of a shape a ray crosses: a cylinder's side or one of its caps (every other shape
// has only its surface, called its side here).
enum class ShapePart : uint8_t { side, bottom_cap, top_cap };

// Where a ray crosses a shape. The exact t is kept in double so that the hit's normal and uv,
// completed from it later, are those intersect_shape gives: a ray's nearest hit (or an occlusion
// test) need not compute them for every shape it crosses.
struct ShapeCrossing {
  double t = 0;
  ShapePart part = ShapePart::side;
};

// Nearest crossing with t in (tmin, tmax); false when there is none.
bool cross_shape(const ShapeDesc& shape, const Ray& ray, float tmin, ShapeCrossing& crossing);
// The hit at a crossing that cross_shape found for this shape and ray.
ShapeHit complete_shape_hit(const ShapeDesc& shape, const Ray& ray, const ShapeCrossing& crossing);

// Nearest hit with t in (tmin, tmax); false when there is none.
bool intersect_shape(const ShapeDesc& shape, const Ray& ray, float tmin, ShapeHit& hit);

// Reprojects an approximate hit point (with the hit's normal) onto the shape and bounds the
// rounding error of the result.
void refine_shape_point(const ShapeDesc& shape, vec3 approximate, vec3 normal, vec3& point, vec3& error);

}  // namespace radiant
