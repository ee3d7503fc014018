// The surface as seen by the incoming ray: normals flipped to face it, normal map applied.
#pragma once

#include "accel/scene_accel.h"
#include "materials/surface.h"
#include "integrators/effect_variants.h"

namespace radiant {

struct HitShading {
  vec3 geometric_normal;  // facing the incoming ray
  vec3 normal;            // shading normal, facing the incoming ray
  vec3 authored_normal;   // shading normal on the authored front side (for transmission)
  vec3 wo;                // unit direction towards where the ray came from
  bool entering = true;   // the ray arrived on the front side
};

// The normal the BSDF sees: facing the incoming ray for opaque materials, the authored one for
// transmissive materials, whose BSDF tells entering from leaving by the side wo lies on.
inline vec3 bsdf_normal(const SurfaceMaterial& m, const HitShading& f) {
  bool transmissive = !is_black(m.kt) || m.transmission > 0;
  return transmissive ? f.authored_normal : f.normal;
}

template <uint32_t E>
HitShading make_hit_shading(uint32_t effects, const SurfaceHit& hit, const SurfaceMaterial& m, vec3 ray_direction) {
  HitShading f;
  f.wo = -normalize(ray_direction);
  vec3 n = hit.shading_normal;
  if (enabled<E>(effects, effect_normal_maps)) {
    if (m.has_normal_map && (hit.tangent.x != 0 || hit.tangent.y != 0 || hit.tangent.z != 0))
      n = apply_normal_map(n, hit.tangent, m.normal_map_sample);
    if (m.has_bump_map) n = apply_bump_map(n, hit.dpdu, hit.dpdv, m.height_slope);
  }
  f.authored_normal = n;
  f.entering = hit.front_face;
  f.geometric_normal = hit.front_face ? hit.geometric_normal : -hit.geometric_normal;
  f.normal = hit.front_face ? n : -n;
  return f;
}

}  // namespace radiant
