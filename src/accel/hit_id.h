// The identity of a ray's hit, as the accelerator reports it before the hit is decoded.
#pragma once

#include <cstdint>

#include "math/vec.h"

namespace radiant {

// Where a ray hit: either a triangle of an instance or an analytic shape.
struct HitId {
  int instance = -1;   // >= 0 for triangles
  int shape = -1;      // >= 0 for analytic shapes
  uint32_t primitive = 0;
  float t = 0;
  vec2 barycentric;    // Embree's (u, v) for triangles, the shape's uv for shapes
  vec3 geometric_normal_raw;  // Embree's Ng (unnormalised, world space for shapes)
  bool valid() const { return instance >= 0 || shape >= 0; }
};

}  // namespace radiant
