#include "accel/analytic_shapes.h"

#include <cmath>

#include "math/dvec3.h"

namespace radiant {

namespace {

// Roots of a t^2 + b t + c with the numerically stable formulation (no cancellation).
bool solve_quadratic(double a, double b, double c, double& t0, double& t1) {
  if (a == 0) return false;
  double discriminant = b * b - 4 * a * c;
  if (discriminant < 0) return false;
  double root = std::sqrt(discriminant);
  double q = b < 0 ? -0.5 * (b - root) : -0.5 * (b + root);
  if (q == 0) {
    t0 = t1 = -b / (2 * a);
    return true;
  }
  t0 = q / a;
  t1 = c / q;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

bool accept(double t, float tmin, float tmax) { return t > tmin && t < tmax; }

bool cross_sphere(const ShapeDesc& s, const Ray& ray, float tmin, double& t) {
  dvec3 o = to_double(ray.origin) - to_double(s.center);
  dvec3 d = to_double(ray.direction);
  double r = s.radius;
  // a t^2 + b t + c with c = |o|^2 - r^2 factored to keep precision for rays starting on it.
  double a = dot(d, d), b = 2 * dot(o, d);
  double distance = std::sqrt(dot(o, o));
  double c = (distance - r) * (distance + r);
  double t0, t1;
  if (!solve_quadratic(a, b, c, t0, t1)) return false;
  t = accept(t0, tmin, ray.tmax) ? t0 : t1;
  return accept(t, tmin, ray.tmax);
}

void complete_sphere(const ShapeDesc& s, const Ray& ray, double t, ShapeHit& hit) {
  dvec3 p = to_double(ray.origin) - to_double(s.center) + to_double(ray.direction) * t;
  double len = std::sqrt(dot(p, p));
  hit.normal = to_float(p * (1 / len));
  double phi = std::atan2(p.y, p.x);
  hit.uv = {float((phi + M_PI) / (2 * M_PI)), float(std::acos(std::clamp(p.z / len, -1.0, 1.0)) / M_PI)};
}

bool cross_plane(const ShapeDesc& s, const Ray& ray, float tmin, double& t) {
  dvec3 n = to_double(s.axis);
  double denominator = dot(to_double(ray.direction), n);
  if (denominator == 0) return false;  // parallel, including a ray lying in the plane
  t = dot(to_double(s.center) - to_double(ray.origin), n) / denominator;
  return accept(t, tmin, ray.tmax);
}

void complete_plane(const ShapeDesc& s, const Ray& ray, double t, ShapeHit& hit) {
  hit.normal = s.axis;
  vec3 tangent, bitangent;
  orthonormal_basis(s.axis, tangent, bitangent);
  dvec3 p = to_double(ray.origin) + to_double(ray.direction) * t - to_double(s.center);
  hit.uv = {float(dot(p, to_double(tangent))), float(dot(p, to_double(bitangent)))};
}

// The side of a cylinder or tube at parameter t: the point's height along the axis and its
// offset from the axis.
void side_point(const ShapeDesc& s, const Ray& ray, double t, double& height, dvec3& radial) {
  dvec3 axis = to_double(s.axis);
  dvec3 p = to_double(ray.origin) - to_double(s.center) + to_double(ray.direction) * t;
  height = dot(p, axis);
  radial = p - axis * height;
}

// Side of a cylinder or tube: the quadratic in the plane orthogonal to the axis.
bool cross_side(const ShapeDesc& s, const Ray& ray, float tmin, float tmax, bool capped, double& t) {
  dvec3 axis = to_double(s.axis);
  dvec3 o = to_double(ray.origin) - to_double(s.center);
  dvec3 d = to_double(ray.direction);
  dvec3 o_perp = o - axis * dot(o, axis);
  dvec3 d_perp = d - axis * dot(d, axis);
  double r = s.radius;
  double a = dot(d_perp, d_perp), b = 2 * dot(o_perp, d_perp);
  double len = std::sqrt(dot(o_perp, o_perp));
  double c = (len - r) * (len + r);
  double roots[2];
  if (!solve_quadratic(a, b, c, roots[0], roots[1])) return false;
  for (double root : roots) {
    if (!accept(root, tmin, tmax)) continue;
    double height;
    dvec3 radial;
    side_point(s, ray, root, height, radial);
    if (capped && (height < 0 || height > s.height)) continue;
    if (dot(radial, radial) == 0) continue;  // on the axis: no normal
    t = root;
    return true;
  }
  return false;
}

void complete_side(const ShapeDesc& s, const Ray& ray, double t, ShapeHit& hit) {
  double height;
  dvec3 radial;
  side_point(s, ray, t, height, radial);
  hit.normal = to_float(radial * (1 / std::sqrt(dot(radial, radial))));
  vec3 tangent, bitangent;
  orthonormal_basis(s.axis, tangent, bitangent);
  double phi = std::atan2(dot(radial, to_double(bitangent)), dot(radial, to_double(tangent)));
  hit.uv = {float((phi + M_PI) / (2 * M_PI)), float(height)};
}

dvec3 cap_center(const ShapeDesc& s, bool top) {
  return to_double(s.center) + to_double(s.axis) * (top ? double(s.height) : 0.0);
}

bool cross_cap(const ShapeDesc& s, const Ray& ray, float tmin, float tmax, bool top, double& t) {
  dvec3 axis = to_double(s.axis);
  dvec3 center = cap_center(s, top);
  double denominator = dot(to_double(ray.direction), axis);
  if (denominator == 0) return false;
  double candidate = dot(center - to_double(ray.origin), axis) / denominator;
  if (!accept(candidate, tmin, tmax)) return false;
  dvec3 p = to_double(ray.origin) + to_double(ray.direction) * candidate - center;
  if (dot(p, p) > double(s.radius) * s.radius) return false;
  t = candidate;
  return true;
}

void complete_cap(const ShapeDesc& s, const Ray& ray, double t, bool top, ShapeHit& hit) {
  dvec3 p = to_double(ray.origin) + to_double(ray.direction) * t - cap_center(s, top);
  hit.normal = top ? s.axis : -s.axis;
  hit.uv = {float(p.x / s.radius), float(p.y / s.radius)};
}

// The nearest of the side and the two caps; each later part must be nearer than the one found.
bool cross_cylinder(const ShapeDesc& s, const Ray& ray, float tmin, ShapeCrossing& crossing) {
  bool found = false;
  float tmax = ray.tmax;
  double t;
  if (cross_side(s, ray, tmin, tmax, true, t)) found = true, crossing = {t, ShapePart::side}, tmax = float(t);
  if (cross_cap(s, ray, tmin, tmax, false, t)) found = true, crossing = {t, ShapePart::bottom_cap}, tmax = float(t);
  if (cross_cap(s, ray, tmin, tmax, true, t)) found = true, crossing = {t, ShapePart::top_cap};
  return found;
}

}  // namespace

bool cross_shape(const ShapeDesc& shape, const Ray& ray, float tmin, ShapeCrossing& crossing) {
  crossing.part = ShapePart::side;
  switch (shape.kind) {
    case ShapeKind::sphere: return cross_sphere(shape, ray, tmin, crossing.t);
    case ShapeKind::plane: return cross_plane(shape, ray, tmin, crossing.t);
    case ShapeKind::cylinder: return cross_cylinder(shape, ray, tmin, crossing);
    case ShapeKind::tube: return cross_side(shape, ray, tmin, ray.tmax, false, crossing.t);
  }
  return false;
}

ShapeHit complete_shape_hit(const ShapeDesc& shape, const Ray& ray, const ShapeCrossing& crossing) {
  ShapeHit hit;
  hit.t = float(crossing.t);
  switch (shape.kind) {
    case ShapeKind::sphere: complete_sphere(shape, ray, crossing.t, hit); break;
    case ShapeKind::plane: complete_plane(shape, ray, crossing.t, hit); break;
    case ShapeKind::cylinder:
    case ShapeKind::tube:
      if (crossing.part == ShapePart::side) complete_side(shape, ray, crossing.t, hit);
      else complete_cap(shape, ray, crossing.t, crossing.part == ShapePart::top_cap, hit);
      break;
  }
  return hit;
}

bool intersect_shape(const ShapeDesc& shape, const Ray& ray, float tmin, ShapeHit& hit) {
  ShapeCrossing crossing;
  if (!cross_shape(shape, ray, tmin, crossing)) return false;
  hit = complete_shape_hit(shape, ray, crossing);
  return true;
}

void refine_shape_point(const ShapeDesc& s, vec3 approximate, vec3 normal, vec3& point, vec3& error) {
  dvec3 p = to_double(approximate), c = to_double(s.center);
  switch (s.kind) {
    case ShapeKind::sphere: {
      dvec3 local = p - c;
      double len = std::sqrt(dot(local, local));
      if (len > 0) p = c + local * (double(s.radius) / len);
      break;
    }
    case ShapeKind::plane: {
      dvec3 n = to_double(s.axis);
      p = p - n * dot(p - c, n);
      break;
    }
    case ShapeKind::cylinder:
    case ShapeKind::tube: {
      dvec3 axis = to_double(s.axis);
      double height = dot(p - c, axis);
      if (std::abs(dot(to_double(normal), axis)) > 0.5) {  // a cap: onto its plane
        double cap = height < 0.5 * s.height ? 0.0 : double(s.height);
        p = p - axis * (height - cap);
      } else {  // the side: radially onto the surface
        dvec3 radial = (p - c) - axis * height;
        double len = std::sqrt(dot(radial, radial));
        if (len > 0) p = c + axis * height + radial * (double(s.radius) / len);
      }
      break;
    }
  }
  point = to_float(p);
  // The only error left is rounding the double result to float (plus margin for the shape
  // parameters being floats), taken on every axis as for triangles.
  float largest = max_component(abs(point)) * rounding_gamma(4);
  if (s.kind != ShapeKind::plane) largest += std::abs(s.radius) * rounding_gamma(4);
  error = {largest, largest, largest};
}

}  // namespace radiant
