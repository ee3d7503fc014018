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

// How many segments a shadow ray may be walked in past see-through occluders before it counts
// as blocked.
constexpr int max_shadow_segments = 64;

// Where a shadow ray towards a light `distance` away along `direction` ends (for a light at
// infinity, the distance infinite, `from` itself: the walk then goes by direction alone).
[[gnu::always_inline]] inline vec3 shadow_target(const SurfaceHit& from, vec3 direction, float distance) {
  return std::isfinite(distance) ? from.position + direction * distance : from.position;
}

// The shadow ray from `from` towards a light `distance` away along `direction` (a light at
// infinity when `distance` is infinite), written into `ray` (see spawn_ray).
[[gnu::always_inline]] inline void set_shadow_ray(Ray& ray, const SurfaceHit& from, vec3 direction, float distance) {
  if (!std::isfinite(distance)) return spawn_ray(ray, from, direction);
  spawn_ray_to(ray, from, from.position + direction * distance);
}

// The light let through past the occluders of a shadow ray whose first segment, `ray`, has
// been traced and hit `id` (invalid: nothing in between): the product of every occluder's
// transmittance, walking on from each towards `target` (towards a light at infinity, where
// ray.tmax is infinite, along ray.direction). Occluders' textures are filtered as material_at's.
// Counts the segments after the first.
template <uint32_t E>
color3 transmittance_past(const RenderContext& ctx, Ray ray, HitId id, vec3 target, bool any_kt, float footprint_scale,
                          RayCounts& counts) {
  bool infinite = !std::isfinite(ray.tmax);
  vec3 direction = ray.direction;
  color3 transmittance = {1, 1, 1};
  SurfaceMaterial resolved;
  // Bounded walk through the occluders; each step leaves the surface it stopped at.
  for (int steps = 1;; ++steps) {
    if (!id.valid()) return transmittance;
    SurfaceHit hit = make_surface_hit(*ctx.accel, ray, id);
    transmittance *= occluder_transmittance(material_at<E>(ctx, id, hit, resolved, footprint_scale), any_kt);
    if (max_component(transmittance) <= 0 || steps == max_shadow_segments) return {0, 0, 0};
    ray = infinite ? spawn_ray(hit, direction) : spawn_ray_to(hit, target);
    counts.shadow++;
    id = intersect_nearest(*ctx.accel, ray);
  }
}

// Transmittance from `from` towards a light `distance` away along `direction` (a light at
// infinity when `distance` is infinite).
template <uint32_t E>
color3 shadow_transmittance(const RenderContext& ctx, const SurfaceHit& from, vec3 direction, float distance,
                            bool any_kt, float footprint_scale, RayCounts& counts) {
  if (!enabled<E>(ctx.effects, effect_shadows)) return {1, 1, 1};
  Ray ray;
  set_shadow_ray(ray, from, direction, distance);
  counts.shadow++;
  if (shadows_are_opaque<E>(ctx)) return is_occluded(*ctx.accel, ray) ? color3{0, 0, 0} : color3{1, 1, 1};
  return transmittance_past<E>(ctx, ray, intersect_nearest(*ctx.accel, ray), shadow_target(from, direction, distance),
                               any_kt, footprint_scale, counts);
}

}  // namespace radiant
