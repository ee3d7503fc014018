#include "accel/direct_shapes.h"

#include <cmath>

#include "accel/scene_accel.h"

namespace radiant {

namespace {

using float4 = DirectShapes::float4;
using int4 = int __attribute__((vector_size(16)));

int lane_mask(int4 lanes) {
#ifdef __SSE__
  return __builtin_ia32_movmskps((float4)lanes);
#else
  return (lanes[0] & 1) | (lanes[1] & 2) | (lanes[2] & 4) | (lanes[3] & 8);
#endif
}

// The lanes of a group of four spheres that the ray's segment (0, tmax) may hit: not those
// whose centre lies farther from its line than the radius, nor those wholly behind the origin
// or beyond tmax. Decided in float with a margin of 1e-4 of the distances involved, a thousand
// times float's rounding, so a sphere the exact test (in double) would hit is never culled; NaN
// and overflow cull nothing. Most tests in a scene of a few spheres are misses, and this spares
// them the double-precision quadratic.
int spheres_maybe_hit(const DirectShapes::SphereGroup& group, const Ray& ray) {
  float4 tx = group.x - ray.origin.x, ty = group.y - ray.origin.y, tz = group.z - ray.origin.z;
  const int4 magnitude = {0x7fffffff, 0x7fffffff, 0x7fffffff, 0x7fffffff};
  float4 ax = (float4)((int4)tx & magnitude), ay = (float4)((int4)ty & magnitude), az = (float4)((int4)tz & magnitude);
  float4 largest = ax > ay ? ax : ay;
  largest = largest > az ? largest : az;
  // The margin takes the centre's distance as three times its largest offset: above it, without a root.
  float4 reach = group.radius + 1e-4f * (largest * 3 + group.radius);
  vec3 d = ray.direction;
  float dd = dot(d, d);
  float4 reach2_dd = reach * reach * dd;
  // |d| times the line's distance from the centre, and times the centre's distance along the ray.
  float4 cx = ty * d.z - tz * d.y, cy = tz * d.x - tx * d.z, cz = tx * d.y - ty * d.x;
  float4 off_line2 = cx * cx + cy * cy + cz * cz;
  float4 along = tx * d.x + ty * d.y + tz * d.z, beyond = along - ray.tmax * dd;
  int4 culled = (off_line2 > reach2_dd) | ((along < 0) & (along * along > reach2_dd)) |
                ((beyond > 0) & (beyond * beyond > reach2_dd));
  return ~lane_mask(culled) & 0xF;
}

// Calls visit(shape index) for every shape the ray may hit, spheres culled; stops when it
// returns true.
template <typename Visit>
bool for_each_candidate(const DirectShapes& direct, const Ray& ray, Visit visit) {
  for (const DirectShapes::SphereGroup& group : direct.spheres)
    for (int lanes = spheres_maybe_hit(group, ray); lanes; lanes &= lanes - 1) {
      int shape = group.shape[__builtin_ctz(unsigned(lanes))];
      if (shape >= 0 && visit(shape)) return true;
    }
  for (int shape : direct.others)
    if (visit(shape)) return true;
  return false;
}

}  // namespace

DirectShapes direct_shapes_of(const SceneDesc& scene) {
  DirectShapes direct;
  direct.enabled = scene.instances.empty() && !scene.shapes.empty() && scene.shapes.size() <= max_shapes_traced_directly;
  if (!direct.enabled) return direct;
  for (size_t i = 0; i < scene.shapes.size(); ++i) {
    const ShapeDesc& shape = scene.shapes[i];
    if (shape.kind != ShapeKind::sphere) {
      direct.others.push_back(int(i));
      continue;
    }
    // The padding of a group is a sphere of radius 0 at the origin that no lane ever visits.
    if (direct.spheres.empty() || direct.spheres.back().shape[3] >= 0) {
      DirectShapes::SphereGroup padding = {};
      for (int& lane : padding.shape) lane = -1;
      direct.spheres.push_back(padding);
    }
    DirectShapes::SphereGroup& group = direct.spheres.back();
    int lane = 0;
    while (group.shape[lane] >= 0) ++lane;
    group.x[lane] = shape.center.x, group.y[lane] = shape.center.y, group.z[lane] = shape.center.z;
    group.radius[lane] = shape.radius;
    group.shape[lane] = int(i);
  }
  return direct;
}

bool shape_hit_in_range(float max_ray_coordinate, const Ray& ray, double t) {
  vec3 p = ray.origin + ray.direction * float(t);
  float bound = 0.5f * max_ray_coordinate;
  return std::abs(p.x) <= bound && std::abs(p.y) <= bound && std::abs(p.z) <= bound;
}

HitId nearest_shape_directly(const SceneAccel& accel, const Ray& ray) {
  const std::vector<ShapeDesc>& shapes = accel.scene->shapes;
  // Its tmax shrinks to each nearer hit, as Embree's tfar does; spheres are culled against the
  // whole ray, since a nearer hit is found only later. Only the nearest gets its normal and uv.
  Ray remaining = ray;
  ShapeCrossing nearest;
  int nearest_shape = -1;
  for_each_candidate(accel.direct_shapes, ray, [&](int i) {
    ShapeCrossing crossing;
    if (!cross_shape(shapes[size_t(i)], remaining, 0, crossing) ||
        !shape_hit_in_range(accel.max_ray_coordinate, ray, crossing.t))
      return false;
    remaining.tmax = float(crossing.t);
    nearest = crossing;
    nearest_shape = i;
    return false;
  });
  HitId id;
  if (nearest_shape < 0) return id;
  ShapeHit hit = complete_shape_hit(shapes[size_t(nearest_shape)], ray, nearest);
  id.shape = nearest_shape;
  id.primitive = uint32_t(nearest_shape);
  id.t = hit.t;
  id.barycentric = hit.uv;
  id.geometric_normal_raw = hit.normal;
  return id;
}

bool shapes_block_directly(const SceneAccel& accel, const Ray& ray) {
  const std::vector<ShapeDesc>& shapes = accel.scene->shapes;
  return for_each_candidate(accel.direct_shapes, ray, [&](int i) {
    ShapeCrossing crossing;
    return cross_shape(shapes[size_t(i)], ray, 0, crossing) &&
           shape_hit_in_range(accel.max_ray_coordinate, ray, crossing.t);
  });
}

}  // namespace radiant
