// The identity of a ray's hit, as the accelerator reports it before the hit is decoded.
#pragma once

#include <cstdint>

#include "math/vec.h"

namespace radiant {

// Where a ray hit: a triangle of an instance, an analytic shape, or a line or point.
struct HitId {
  int instance = -1;   // >= 0 for triangles
  int shape = -1;      // >= 0 for analytic shapes
  int stroke = -1;     // >= 0 for lines and points (primitive: the segment or point)
  uint32_t primitive = 0;
  float t = 0;
  vec2 barycentric;    // Embree's (u, v) for triangles, the shape's uv for shapes
  vec3 geometric_normal_raw;  // Embree's Ng (unnormalised, world space for shapes)
  bool valid() const { return instance >= 0 || shape >= 0 || stroke >= 0; }
};

}  // namespace radiant
