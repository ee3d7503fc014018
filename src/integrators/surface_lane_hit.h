// A surface lane's hit decoded: the triangle's or shape's point with its error bound and its
// normals, by the one-path decoding's code (accel/triangle_point.h), and what a lane stores of it.
#pragma once

#include <cmath>

#include "accel/ray.h"
#include "accel/triangle_point.h"
#include "math/dvec3.h"
#include "math/lane.h"
#include "math/matrix_entries.h"

namespace radiant {

// Internal to the surface lanes: included by surface_lanes.cpp alone, after surface_lanes.h
// (SurfaceLanes), whose unit these files are part of.
namespace {

using lane::largest_float;
using lane::normalize_in_range;
using lane::select;

// A lane's instance transforms (surface_hit.cpp, fill_triangle_hit), as entries for the products
// of math/matrix_entries.h: to the world, and the inverse's 3x3 part for normals.
struct LaneToWorld {
  const SurfaceLanes& l;
  int i;
  [[gnu::always_inline]] float operator()(int r, int c) const { return l.to_world[r * 4 + c][i]; }
};
struct LaneToObject {
  const SurfaceLanes& l;
  int i;
  [[gnu::always_inline]] float operator()(int r, int c) const { return l.to_object[r * 3 + c][i]; }
};

// A sphere's or a plane's hit moved onto the surface in double precision, and its error bound
// (analytic_shapes.cpp, refine_shape_point, from fill_shape_hit's approximate point).
struct ShapePoint {
  vec3 point;
  float error;
};
[[gnu::always_inline]] inline ShapePoint refine_shape_lane(const SurfaceLanes& l, int i, vec3 direction) {
  vec3 approximate = vec3{l.ray_ox[i], l.ray_oy[i], l.ray_oz[i]} + direction * l.ray_t[i];
  dvec3 p = to_double(approximate), c = to_double({l.center_x[i], l.center_y[i], l.center_z[i]});
  float radius = l.radius[i];
  bool sphere = l.shape[i] == SurfaceLanes::sphere_hit;
  dvec3 local = p - c;
  double len = std::sqrt(dot(local, local));
  dvec3 on_sphere = c + local * (double(radius) / len);
  dvec3 n = to_double({l.axis_x[i], l.axis_y[i], l.axis_z[i]});
  dvec3 on_plane = p - n * dot(p - c, n);
  // Chosen after rounding to float, by 32-bit masks: SSE2 has no 64-bit compare to make double
  // masks from, and as ternaries GCC branches. len > 0 exactly when its float is: p and c are
  // floats, so a nonzero len is at least their smallest nonzero difference, a float.
  bool moves = float(len) > 0;
  vec3 sphere_point = lane::select_bits(moves, to_float(on_sphere), approximate);
  ShapePoint s;
  s.point = lane::select_bits(sphere, sphere_point, to_float(on_plane));
  s.error = max_component(abs(s.point)) * rounding_gamma(4);
  s.error = lane::select_bits(sphere, s.error + std::abs(radius) * rounding_gamma(4), s.error);
  return s;
}

// A lane's hit: make_surface_hit for a triangle (surface_hit.cpp, fill_triangle_hit) and
// make_hit_shading. `in_range` is false where a normalize() the one-path code does would have
// rescaled. `Hits`: which kinds of hit beside untransformed triangles the lanes hold
// (SurfaceLanes::hit_kinds), each decoded only where some lane needs it.
struct LaneHit {
  vec3 point;
  float error;  // the position's error bound, the same along every axis
  vec3 geometric_normal;
  vec3 normal;  // the shading normal facing the ray (HitShading::normal)
  vec3 wo;
  bool in_range;
};
template <int Hits>
[[gnu::always_inline]] inline LaneHit decode_lane(const SurfaceLanes& l, int i) {
  LaneHit hit;
  vec3 p0 = {l.p0x[i], l.p0y[i], l.p0z[i]}, p1 = {l.p1x[i], l.p1y[i], l.p1z[i]}, p2 = {l.p2x[i], l.p2y[i], l.p2z[i]};
  float b1 = l.b1[i], b2 = l.b2[i];
  vec3 direction = {l.dx[i], l.dy[i], l.dz[i]};
  vec3 e1 = p1 - p0, e2 = p2 - p0;
  TrianglePoint object = triangle_point(p0, e1, e2, b1, b2);
  // Untransformed, Embree's Ng; transformed, the object normal's image.
  vec3 geometric = {l.ngx[i], l.ngy[i], l.ngz[i]};
  bool transformed = false;
  hit.point = object.point;
  vec3 error = object.error;
  if constexpr ((Hits & SurfaceLanes::transformed_hits) != 0) {
    transformed = l.transformed[i] != 0;
    vec3 world_error = world_point_error(LaneToWorld{l, i}, object.point, object.error);
    hit.point = lane::select_bits(transformed, transform_point_by(LaneToWorld{l, i}, object.point), object.point);
    error = lane::select_bits(transformed, world_error, object.error);
    geometric = lane::select_bits(transformed, transform_normal_by(LaneToObject{l, i}, cross(e1, e2)), geometric);
  }
  hit.error = max_component(error);
  if constexpr ((Hits & SurfaceLanes::shape_hits) != 0) {
    bool shape = l.shape[i] != SurfaceLanes::triangle_hit;
    ShapePoint refined = refine_shape_lane(l, i, direction);
    hit.point = lane::select_bits(shape, refined.point, hit.point);
    hit.error = lane::select_bits(shape, refined.error, hit.error);
  }
  bool normal_in_range, direction_in_range;
  hit.geometric_normal = normalize_in_range(geometric, normal_in_range);
  if constexpr ((Hits & SurfaceLanes::transformed_hits) != 0)
    hit.geometric_normal = lane::select_bits(transformed, hit.geometric_normal * l.orientation[i], hit.geometric_normal);
  bool front_face = dot(direction, hit.geometric_normal) < 0;
  // Interpolated vertex normals, on the geometric normal's side, where they are usable.
  float b0 = 1 - b1 - b2;
  vec3 interpolated = barycentric_mix(vec3{l.n0x[i], l.n0y[i], l.n0z[i]}, vec3{l.n1x[i], l.n1y[i], l.n1z[i]},
                                      vec3{l.n2x[i], l.n2y[i], l.n2z[i]}, b0, b1, b2);
  if constexpr ((Hits & SurfaceLanes::transformed_hits) != 0)
    interpolated = lane::select_bits(transformed, transform_normal_by(LaneToObject{l, i}, interpolated), interpolated);
  bool has_normals = l.normals[i] == SurfaceLanes::vertex_normals, interpolated_in_range;
  vec3 n = normalize_in_range(interpolated, interpolated_in_range);
  bool usable = has_normals & usable_vertex_normal(n);
  vec3 shading_normal = usable ? on_side_of(n, hit.geometric_normal) : hit.geometric_normal;
  bool given = l.normals[i] == SurfaceLanes::given_normal;
  shading_normal = lane::select_bits(given, vec3{l.n0x[i], l.n0y[i], l.n0z[i]}, shading_normal);
  hit.wo = -normalize_in_range(direction, direction_in_range);
  hit.normal = front_face ? shading_normal : -shading_normal;
  hit.in_range = normal_in_range & direction_in_range & (interpolated_in_range | !has_normals);
  return hit;
}

// What every lane stores of its hit for the outputs and the later loops.
[[gnu::always_inline]] inline void store_hit(SurfaceLanes& l, int i, const LaneHit& hit, vec3 lobe_normal, bool valid) {
  l.fallback[i] = !hit.in_range;
  l.px[i] = hit.point.x, l.py[i] = hit.point.y, l.pz[i] = hit.point.z;
  l.nx[i] = hit.normal.x, l.ny[i] = hit.normal.y, l.nz[i] = hit.normal.z;
  l.gnx[i] = hit.geometric_normal.x, l.gny[i] = hit.geometric_normal.y, l.gnz[i] = hit.geometric_normal.z;
  l.error[i] = hit.error;
  l.lobe_nx[i] = lobe_normal.x, l.lobe_ny[i] = lobe_normal.y, l.lobe_nz[i] = lobe_normal.z;
  l.valid[i] = valid;
}
[[gnu::always_inline]] inline void store_bounce(SurfaceLanes& l, int i, bool scatters, vec3 origin, vec3 wi,
                                                float pdf, color3 weight, bool delta = false) {
  l.scatters[i] = scatters;
  l.delta[i] = delta;
  l.ox[i] = origin.x, l.oy[i] = origin.y, l.oz[i] = origin.z;
  l.wix[i] = wi.x, l.wiy[i] = wi.y, l.wiz[i] = wi.z;
  l.pdf[i] = pdf;
  l.weight_r[i] = weight.x, l.weight_g[i] = weight.y, l.weight_b[i] = weight.z;
}

}  // namespace

}  // namespace radiant
