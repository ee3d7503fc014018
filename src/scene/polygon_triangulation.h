// Triangulating one planar polygon, convex or not, by ear clipping in its own plane (shared by
// the OBJ loader and the .scene format's @polygon).
#pragma once

#include <cstdint>
#include <vector>

#include "math/vec.h"

namespace radiant {

struct PolygonTriangles {
  std::vector<uint32_t> corners;  // three per triangle: indices into the polygon's corners
  // False when two of its edges cross (up to 4096 corners), or when no ear could be found before
  // the polygon was used up (the work limit): triangles may then overlap (the rest is a fan).
  bool simple = true;
};

// Triangles covering the polygon `corners` (in order, winding kept): ear clipping in the plane of
// Newell's normal, in double precision. Repeated corners and corners on a straight line between
// their neighbours are passed over, so an annulus written as one polygon with a bridge edge
// (walked there and back) keeps its hole. A polygon without area gives no triangles.
PolygonTriangles triangulate_polygon(const std::vector<vec3>& corners);

// Bytes triangulate_polygon works in per corner (projected points, the corner list, the output),
// with the caller's corner positions and indices.
constexpr uint64_t polygon_triangulation_bytes_per_corner = 16 + 8 + 12 + 12 + 4 + 12;

}  // namespace radiant
