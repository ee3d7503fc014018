// Matrix products written once over a matrix given by its entries `a(row, column)`: a mat4's
// (Mat4Entries), or one lane's of the batch's matrices (integrators/surface_lanes.cpp,
// math/lane.h), so that one path's hit and a lane's are moved into the world by the same code.
#pragma once

#include <cmath>

#include "math/transform.h"
#include "math/vec.h"

namespace radiant {

template <class Entry>
[[gnu::always_inline]] inline vec3 transform_point_by(const Entry& a, vec3 p) {
  return {a(0, 0) * p.x + a(0, 1) * p.y + a(0, 2) * p.z + a(0, 3), a(1, 0) * p.x + a(1, 1) * p.y + a(1, 2) * p.z + a(1, 3),
          a(2, 0) * p.x + a(2, 1) * p.y + a(2, 2) * p.z + a(2, 3)};
}
template <class Entry>
[[gnu::always_inline]] inline vec3 transform_vector_by(const Entry& a, vec3 v) {
  return {a(0, 0) * v.x + a(0, 1) * v.y + a(0, 2) * v.z, a(1, 0) * v.x + a(1, 1) * v.y + a(1, 2) * v.z,
          a(2, 0) * v.x + a(2, 1) * v.y + a(2, 2) * v.z};
}
// transform_vector by the matrix of |a|'s entries: how far errors in v's coordinates can move the
// result (hit positions' error bounds).
template <class Entry>
[[gnu::always_inline]] inline vec3 abs_transform_vector_by(const Entry& a, vec3 v) {
  return transform_vector_by([&](int r, int c) { return std::abs(a(r, c)); }, v);
}
// Normals transform by the inverse transpose; pass the inverse matrix.
template <class Entry>
[[gnu::always_inline]] inline vec3 transform_normal_by(const Entry& inverse, vec3 n) {
  return transform_vector_by([&](int r, int c) { return inverse(c, r); }, n);
}

// A mat4's entries, for the products above.
struct Mat4Entries {
  const mat4& a;
  [[gnu::always_inline]] float operator()(int r, int c) const { return a.m[r][c]; }
};

}  // namespace radiant
