#include "scene/scene_bounds.h"

#include <limits>

#include "scene/shape_bounds.h"

namespace radiant {

bool scene_bounds(const SceneDesc& scene, vec3& lower_out, vec3& upper_out) {
  constexpr float inf = std::numeric_limits<float>::infinity();
  vec3 lower = {inf, inf, inf}, upper = -lower;
  for (const InstanceDesc& instance : scene.instances)
    for (vec3 p : scene.meshes[instance.mesh].positions) {
      vec3 w = transform_point(instance.transform, p);
      lower = min(lower, w);
      upper = max(upper, w);
    }
  for (const ShapeDesc& shape : scene.shapes) {
    if (shape.kind == ShapeKind::plane || shape.kind == ShapeKind::tube) continue;
    vec3 lo, hi;
    shape_bounds(shape, 0, lo, hi);
    lower = min(lower, lo);
    upper = max(upper, hi);
  }
  for (const StrokeDesc& stroke : scene.strokes)
    for (vec3 p : stroke.positions) {
      lower = min(lower, stroke.center + p);
      upper = max(upper, stroke.center + p);
    }
  if (!(lower.x <= upper.x)) return false;
  lower_out = lower;
  upper_out = upper;
  return true;
}

}  // namespace radiant
