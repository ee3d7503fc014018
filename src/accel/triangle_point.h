// A triangle hit's point with its rounding-error bound, and its shading normal, written once over
// a lane (math/lane.h): make_surface_hit (surface_hit.cpp) decodes one path's hit with these, the
// batch's SIMD lanes (integrators/surface_lanes.cpp) decode theirs with the same code.
#pragma once

#include "accel/ray.h"
#include "math/lane.h"
#include "math/matrix_entries.h"
#include "math/vec.h"

namespace radiant {

struct TrianglePoint {
  vec3 point;
  vec3 error;  // per-axis bound on the point's rounding error
};

// The point at barycentrics (b1, b2) of the triangle p0 + edges e1, e2, in its own space.
// Barycentric interpolation is far more accurate than origin + t * direction (pbrt 6.8.4).
// Written from a vertex along the edges, its rounding scales with the triangle's size, not
// with its distance from the origin: only the final addition to p0 rounds at p0's magnitude
// (edges of nearby vertices subtract exactly; their bound is kept anyway). A barycentric
// error moves the point within the plane, which no offset needs to cover.
[[gnu::always_inline]] inline TrianglePoint triangle_point(vec3 p0, vec3 e1, vec3 e2, float b1, float b2) {
  vec3 point = p0 + (b1 * e1 + b2 * e2);
  return {point, rounding_gamma(5) * (abs(b1 * e1) + abs(b2 * e2)) + rounding_gamma(2) * abs(point)};
}

// The error bound of an object-space point and its bound once `to_world` (entries `m(row,
// column)`, math/matrix_entries.h) has moved the point into the world.
template <class Entry>
[[gnu::always_inline]] inline vec3 world_point_error(const Entry& to_world, vec3 object_point, vec3 object_error) {
  vec3 translation = {to_world(0, 3), to_world(1, 3), to_world(2, 3)};
  return (1 + rounding_gamma(3)) * abs_transform_vector_by(to_world, object_error) +
         rounding_gamma(3) * (abs_transform_vector_by(to_world, abs(object_point)) + abs(translation));
}

// The values at barycentrics (b0, b1, b2) of a triangle's three vertex values.
template <class T>
[[gnu::always_inline]] inline T barycentric_mix(const T& v0, const T& v1, const T& v2, float b0, float b1, float b2) {
  return v0 * b0 + v1 * b1 + v2 * b2;
}

// Whether an interpolated vertex normal, normalised, can shade: finite and not collapsed (the
// vertex normals of a corner can cancel).
[[gnu::always_inline]] inline bool usable_vertex_normal(vec3 n) {
  return lane::finite(n) & (length_squared(n) > 0.5f);
}
// `n` on the side of `side`: interpolated normals live on the geometric normal's side.
[[gnu::always_inline]] inline vec3 on_side_of(vec3 n, vec3 side) { return dot(n, side) < 0 ? -n : n; }

}  // namespace radiant
