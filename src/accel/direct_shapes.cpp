#include "accel/direct_shapes.h"

#include <cmath>
#include <utility>


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

// The spheres that the ray's segment (0, tmax) may hit, as a mask of sphere slots (four per
// group, bit 4 * group + lane): not those whose centre lies farther from its line than the
// radius, nor those wholly behind the origin or beyond tmax. Decided in float with a margin of
// 1e-4 of the distances involved, a thousand times float's rounding, so a sphere the exact test
// (in double) would hit is never culled; NaN and overflow cull nothing. Most tests in a scene of
// a few spheres are misses, and this spares them the double-precision quadratic. The ray's own
// terms are set up once for all groups.
uint32_t spheres_maybe_hit(const std::vector<DirectShapes::SphereGroup>& groups, const Ray& ray) {
  const float4 ox = ray.origin.x - float4{}, oy = ray.origin.y - float4{}, oz = ray.origin.z - float4{};
  const float4 dx = ray.direction.x - float4{}, dy = ray.direction.y - float4{}, dz = ray.direction.z - float4{};
  const float dd = dot(ray.direction, ray.direction);
  const float tmax_dd = ray.tmax * dd;
  // The margin bounds the distance from origin to centre by 3 (|origin|max + |centre|max), which
  // splits into a part of the ray's and one the group keeps (SphereGroup::reach).
  const float origin_margin = 3e-4f * max_component(abs(ray.origin));
  uint32_t candidates = 0;
  for (size_t g = 0; g < groups.size(); ++g) {
    const DirectShapes::SphereGroup& group = groups[g];
    float4 tx = group.x - ox, ty = group.y - oy, tz = group.z - oz;
    float4 reach = group.reach + origin_margin;
    float4 reach2_dd = reach * reach * dd;
    // |d| times the line's distance from the centre, and times the centre's distance along the ray.
    float4 cx = ty * dz - tz * dy, cy = tz * dx - tx * dz, cz = tx * dy - ty * dx;
    float4 off_line2 = cx * cx + cy * cy + cz * cz;
    float4 along = tx * dx + ty * dy + tz * dz, beyond = along - tmax_dd;
    int4 culled = (off_line2 > reach2_dd) | ((along < 0) & (along * along > reach2_dd)) |
                  ((beyond > 0) & (beyond * beyond > reach2_dd));
    candidates |= uint32_t(~lane_mask(culled) & group.lanes) << (4 * g);
  }
  return candidates;
}

// Calls visit(shape index) for every shape the ray may hit, spheres culled; stops when it
// returns true.
template <typename Visit>
bool for_each_candidate(const DirectShapes& direct, const Ray& ray, Visit visit) {
  for (uint32_t slots = spheres_maybe_hit(direct.spheres, ray); slots; slots &= slots - 1) {
    unsigned slot = unsigned(__builtin_ctz(slots));
    if (visit(direct.spheres[slot / 4].shape[slot % 4])) return true;
  }
  for (int shape : direct.others)
    if (visit(shape)) return true;
  return false;
}

// The first free lane of the last group, a new group when it is full. Lanes no sphere fills are
// all zeros and are never visited (`lanes` leaves them out).
std::pair<DirectShapes::SphereGroup&, int> next_lane(std::vector<DirectShapes::SphereGroup>& groups) {
  if (groups.empty() || groups.back().lanes == 0xF) groups.emplace_back();
  DirectShapes::SphereGroup& group = groups.back();
  int lane = __builtin_ctz(unsigned(~group.lanes));
  group.lanes |= 1 << lane;
  return {group, lane};
}

}  // namespace

DirectShapes direct_shapes_of(const SceneDesc& scene) {
  DirectShapes direct;
  direct.enabled = scene.instances.empty() && scene.strokes.empty() && !scene.shapes.empty() &&
                   scene.shapes.size() <= max_shapes_traced_directly;
  if (!direct.enabled) return direct;
  for (size_t i = 0; i < scene.shapes.size(); ++i) {
    const ShapeDesc& shape = scene.shapes[i];
    if (shape.kind == ShapeKind::sphere) {
      auto [group, lane] = next_lane(direct.spheres);
      group.x[lane] = shape.center.x, group.y[lane] = shape.center.y, group.z[lane] = shape.center.z;
      group.reach[lane] = shape.radius + 1e-4f * (3 * max_component(abs(shape.center)) + shape.radius);
      group.shape[lane] = int(i);
    } else {
      direct.others.push_back(int(i));
    }
  }
  return direct;
}

bool shape_hit_in_range(float max_ray_coordinate, const Ray& ray, double t) {
  vec3 p = ray.origin + ray.direction * float(t);
  float bound = 0.5f * max_ray_coordinate;
  return std::abs(p.x) <= bound && std::abs(p.y) <= bound && std::abs(p.z) <= bound;
}

HitId nearest_shape_directly(const DirectShapes& direct, const std::vector<ShapeDesc>& shapes, float max_ray_coordinate,
                             const Ray& ray) {
  // Its tmax shrinks to each nearer hit, as Embree's tfar does; spheres are culled against the
  // whole ray, since a nearer hit is found only later. Only the nearest gets its normal and uv.
  Ray remaining = ray;
  ShapeCrossing nearest;
  int nearest_shape = -1;
  for_each_candidate(direct, ray, [&](int i) {
    ShapeCrossing crossing;
    if (!cross_shape(shapes[size_t(i)], remaining, 0, crossing) ||
        !shape_hit_in_range(max_ray_coordinate, ray, crossing.t))
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

bool shapes_block_directly(const DirectShapes& direct, const std::vector<ShapeDesc>& shapes, float max_ray_coordinate,
                           const Ray& ray) {
  return for_each_candidate(direct, ray, [&](int i) {
    ShapeCrossing crossing;
    return cross_shape(shapes[size_t(i)], ray, 0, crossing) &&
           shape_hit_in_range(max_ray_coordinate, ray, crossing.t);
  });
}

}  // namespace radiant
