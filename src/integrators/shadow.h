// How much of a light's contribution reaches a point past the geometry in between.
#pragma once

#include "integrators/render_context.h"

namespace radiant {

// Fraction of light passing one occluder: straight-through transmission and alpha see-through.
// `any_kt`: Whitted counts every kt (its model bends nothing for shadows); the path tracer only
// the transmission that does not refract (ior == 1), the rest arrives by BSDF sampling.
inline color3 occluder_transmittance(const SurfaceMaterial& m, bool any_kt) {
  color3 kt = (any_kt || m.ior == 1.0f) ? m.kt : color3{0, 0, 0};
  return kt * m.opacity + color3{1, 1, 1} * (1 - m.opacity);
}

// Whether shadow rays only ask "blocked or not": no occluder lets light through, so one
// occlusion query per light sample decides, and a batch of them can be traced together.
template <uint32_t E>
bool shadows_are_opaque(const RenderContext& ctx) {
  return enabled<E>(ctx.effects, effect_shadows) && !enabled<E>(ctx.effects, effect_transparent_shadows) &&
         !enabled<E>(ctx.effects, effect_alpha);
}

// The shadow ray from `from` towards a light `distance` away along `direction` (a light at
// infinity when `distance` is infinite), written into `ray` (see spawn_ray).
[[gnu::always_inline]] inline void set_shadow_ray(Ray& ray, const SurfaceHit& from, vec3 direction, float distance) {
  if (!std::isfinite(distance)) return spawn_ray(ray, from, direction);
  spawn_ray_to(ray, from, from.position + direction * distance);
}

// Transmittance from `from` towards a light at `target` (or along `direction` for lights at
// infinity when `distance` is infinite); occluders' textures are filtered as material_at's.
template <uint32_t E>
color3 shadow_transmittance(const RenderContext& ctx, const SurfaceHit& from, vec3 direction, float distance,
                            bool any_kt, float footprint_scale, RayCounts& counts) {
  if (!enabled<E>(ctx.effects, effect_shadows)) return {1, 1, 1};
  Ray ray;
  set_shadow_ray(ray, from, direction, distance);
  if (shadows_are_opaque<E>(ctx)) {
    counts.shadow++;
    return is_occluded(*ctx.accel, ray) ? color3{0, 0, 0} : color3{1, 1, 1};
  } else {
    bool infinite = !std::isfinite(distance);
    vec3 target = from.position + direction * (infinite ? 0.0f : distance);
    color3 transmittance = {1, 1, 1};
    SurfaceMaterial resolved;
    // Bounded walk through the occluders; each step leaves the surface it stopped at.
    for (int step = 0; step < 64; ++step) {
      counts.shadow++;
      HitId id = intersect_nearest(*ctx.accel, ray);
      if (!id.valid()) return transmittance;
      SurfaceHit hit = make_surface_hit(*ctx.accel, ray, id);
      transmittance *= occluder_transmittance(material_at<E>(ctx, id, hit, resolved, footprint_scale), any_kt);
      if (max_component(transmittance) <= 0) return {0, 0, 0};
      ray = infinite ? spawn_ray(hit, direction) : spawn_ray_to(hit, target);
    }
    return {0, 0, 0};
  }
}

}  // namespace radiant
