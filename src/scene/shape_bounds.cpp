#include "scene/shape_bounds.h"

#include <algorithm>
#include <cmath>

namespace radiant {

void shape_bounds(const ShapeDesc& s, float infinite_extent, vec3& lower, vec3& upper) {
  switch (s.kind) {
    case ShapeKind::sphere: {
      vec3 r = {s.radius, s.radius, s.radius};
      lower = s.center - r;
      upper = s.center + r;
      return;
    }
    case ShapeKind::cylinder: {
      // Each axis-aligned extent of a disk of radius r with unit normal a is r*sqrt(1-a_i^2).
      vec3 a = s.axis;
      vec3 disk = {s.radius * std::sqrt(std::max(0.0f, 1 - a.x * a.x)),
                   s.radius * std::sqrt(std::max(0.0f, 1 - a.y * a.y)),
                   s.radius * std::sqrt(std::max(0.0f, 1 - a.z * a.z))};
      vec3 top = s.center + s.axis * s.height;
      lower = min(s.center, top) - disk;
      upper = max(s.center, top) + disk;
      return;
    }
    case ShapeKind::plane:
    case ShapeKind::tube: {
      vec3 e = {infinite_extent, infinite_extent, infinite_extent};
      lower = -e;
      upper = e;
      return;
    }
  }
}

}  // namespace radiant
