#include "integrators/whitted.h"

#include <cmath>

#include "integrators/background.h"
#include "integrators/hit_shading.h"
#include "materials/bsdf.h"
#include "integrators/shadow.h"
#include "lights/delta_light.h"

namespace radiant {

namespace {

enum class RayKind { camera, reflection, refraction };

template <uint32_t E>
color3 direct_phong(const RenderContext& ctx, const SurfaceHit& hit, const SurfaceMaterial& m,
                    const HitShading& f, float footprint_scale, RayCounts& counts) {
  color3 sum;
  if (enabled<E>(ctx.effects, effect_direct_delta)) {
    for (int index : ctx.lights->delta_lights) {
      DeltaLightSample light;
      if (!sample_delta_light(ctx.scene->lights[index], hit.position, light)) continue;
      float cos_theta = dot(f.normal, light.direction);
      // Light and viewer must be on the same side of the surface.
      if (cos_theta <= 0 || dot(f.geometric_normal, light.direction) <= 0) continue;
      float highlight = 0;
      if (!is_black(m.ks)) highlight = std::pow(std::max(0.0f, dot(reflect(light.direction, f.normal), f.wo)), m.shininess);
      color3 response = m.kd * cos_theta + m.ks * highlight;
      if (is_black(response)) continue;
      color3 transmittance = shadow_transmittance<E>(ctx, hit, light.direction, light.distance, true,
                                                             footprint_scale, counts);
      sum += transmittance * light.irradiance * response * inv_pi;
    }
  }
  return sum;
}

template <uint32_t E>
color3 trace(const RenderContext& ctx, const Ray& ray, int depth, int see_through, color3 weight, RayKind kind,
             float footprint_scale, RayCounts& counts, FirstHit* first_hit, const HitId* known_hit = nullptr) {
  switch (kind) {
    case RayKind::camera: counts.camera++; break;
    case RayKind::reflection: counts.reflection++; break;
    case RayKind::refraction: counts.refraction++; break;
  }
  HitId id = known_hit ? *known_hit
                       : intersect_nearest(*ctx.accel, ray, kind == RayKind::camera ? camera_culling(ctx) : FaceCulling::none);
  if (!id.valid()) {
    if (kind == RayKind::camera) return camera_background<E>(ctx, ray.direction);
    return background_radiance<E>(ctx, ray.direction);
  }
  SurfaceHit hit = make_surface_hit(*ctx.accel, ray, id);
  SurfaceMaterial resolved;
  const SurfaceMaterial& m = material_at<E>(ctx, id, hit, resolved, footprint_scale);
  HitShading f = make_hit_shading<E>(ctx.effects, hit, m, ray.direction);
  if (first_hit) *first_hit = {bsdf_albedo(m), f.normal, id.t * length(ray.direction), 1};

  color3 radiance;
  if (enabled<E>(ctx.effects, effect_emission)) radiance += m.emission;
  if (m.unlit) return m.base_color;
  if (enabled<E>(ctx.effects, effect_ambient)) radiance += m.ka * ctx.ambient;
  radiance += direct_phong<E>(ctx, hit, m, f, footprint_scale, counts);

  if (depth + 1 >= ctx.max_depth) return radiance;
  // Total internal reflection is part of refraction: its share reflects even when no material in
  // the scene has kr, i.e. when the reflection effect is off.
  color3 reflected_weight = enabled<E>(ctx.effects, effect_reflection) ? m.kr : color3{};
  if (enabled<E>(ctx.effects, effect_refraction)) {
    if (!is_black(m.kt)) {
      float eta = f.entering ? m.ior : 1 / m.ior;
      vec3 transmitted;
      if (refract(f.wo, f.normal, eta, transmitted)) {
        color3 w = weight * m.kt;
        if (max_component(w) >= ctx.contribution_cutoff)
          radiance += m.kt * trace<E>(ctx, spawn_ray(hit, transmitted), depth + 1, see_through, w, RayKind::refraction,
                                       footprint_scale, counts, nullptr);
      } else {
        reflected_weight += m.kt;  // total internal reflection: the transmitted share reflects
      }
    }
  }
  color3 w = weight * reflected_weight;
  if (!is_black(reflected_weight) && max_component(w) >= ctx.contribution_cutoff)
    radiance += reflected_weight * trace<E>(ctx, spawn_ray(hit, reflect(f.wo, f.normal)), depth + 1, see_through, w,
                                            RayKind::reflection, footprint_scale, counts, nullptr);
  if (enabled<E>(ctx.effects, effect_alpha)) {
    if (m.opacity < 1) {
      FirstHit behind;  // only its coverage is kept: the AOVs are the first surface's
      color3 beyond;    // black past the last see-through step
      if (see_through + 1 < max_see_through_steps)
        beyond = trace<E>(ctx, spawn_ray(hit, ray.direction), depth, see_through + 1, weight * (1 - m.opacity), kind,
                          footprint_scale, counts, first_hit ? &behind : nullptr);
      radiance = radiance * m.opacity + (1 - m.opacity) * beyond;
      if (first_hit) first_hit->coverage = m.opacity + (1 - m.opacity) * behind.coverage;
    }
  }
  return radiance;
}

template <uint32_t E>
struct WhittedVariant {
  static color3 run(const RenderContext& ctx, const Ray& ray, const SampleContext& sample, RayCounts& counts,
                    FirstHit* first_hit, const HitId* camera_hit) {
    return trace<E>(ctx, ray, 0, 0, {1, 1, 1}, RayKind::camera, texture_footprint_scale(sample.index), counts, first_hit,
                    camera_hit);
  }
  // Whitted's reflection and refraction trees branch per path: its paths run one at a time
  // from their camera hits.
  static void run_batch(const RenderContext& ctx, BatchPath* paths, int count, RayCounts& counts) {
    run_each_path(run, ctx, paths, count, counts);
  }
};

}  // namespace

Integrator select_whitted(uint32_t effects) { return select_variant<Integrator, WhittedVariant>(effects); }

}  // namespace radiant
