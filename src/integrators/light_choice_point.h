// Where the light BVH rates lights for a path vertex: the hit's point along its ray and its
// geometric normal, both known as soon as the ray is traced. The exact position and the shading
// normal come only with the hit's decoding, but the batch chooses the lights of all its paths
// together before any is decoded, so that their descents run side by side. Any point and
// normal near the hit serve for rating lights; what matters is that choosing a light and the
// probability MIS asks for later use the same ones.
#pragma once

#include "accel/scene_accel.h"
#include "math/transform.h"

namespace radiant {

struct LightChoicePoint {
  vec3 position, normal;  // normal: unit, or zero where the hit gives none
};

inline LightChoicePoint light_choice_point(const SceneAccel& accel, const Ray& ray, const HitId& id) {
  vec3 normal = id.geometric_normal_raw;
  // Embree reports a transformed instance's normal in the instance's own space.
  if (id.instance >= 0 && !accel.instance_identity[size_t(id.instance)])
    normal = transform_normal(accel.instance_inverse[size_t(id.instance)], normal);
  normal = normalize(normal);  // a degenerate triangle's zero normal stays zero: no receiver cosine
  if (!is_finite(normal)) normal = {0, 0, 0};
  return {ray.origin + ray.direction * id.t, normal};
}

}  // namespace radiant
