// One path vertex: what it sees and emits, its light sample and bounce, and the path run one
// vertex at a time (PathVariant::run, the reference the batch must match).
#pragma once

#include "integrators/path_variant.h"

namespace radiant {

// Internal to the path integrator: included by path.cpp alone.
namespace {

// The path's vertex at `id`, the hit of path.ray: adds what it sees, takes a light sample
// (its shadow ray left in `light` when light.traces) and sets the next ray. Returns whether
// the path goes on along path.ray. `drawn`, when given, holds random numbers drawn ahead.
// With `SharesFirstVertex` a camera sample's sub-paths share its first vertex's shading through
// `shared` (ctx.split > 1); compiled apart so that one path per camera sample pays nothing.
template <uint32_t E, bool LightSampling>
template <bool SharesFirstVertex>
[[gnu::always_inline]] inline bool PathVariant<E, LightSampling>::advance(const RenderContext& ctx, PathState& path, const HitId& id,
                                           VertexDraws* drawn, VertexScratch& scratch, SharedFirstVertex* shared,
                                           LightSampleResult& light, RayCounts& counts) {
  const LightTable& lights = *ctx.lights;
  int depth = path.depth;
  const SampleContext& sample = depth == 0 ? *path.sample : path.own;
  const Ray& ray = path.ray;
  color3& radiance = path.radiance;
  color3& throughput = path.throughput;
  bool gathers = depth > 0 || path.gathers_first_vertex;  // this vertex's own light
  light.traces = false;
  // Beer-Lambert along the segment just traced inside a volume (a ray escaping one, which a
  // closed mesh cannot let happen, keeps its light).
  if (enabled<E>(ctx.effects, effect_absorption) && path.medium >= 0 && id.valid())
    throughput *= exp(ctx.absorption[size_t(path.medium)] * -(id.t * length(ray.direction)));
  if (!id.valid()) {
    // Depth 0 is the camera ray, also after it passed alpha cutouts: it sees the backdrop.
    if (depth == 0) {
      if (gathers) radiance += clamp_contribution(ctx, throughput * camera_background<E>(ctx, ray.direction), -1);
    } else if (gathers && enabled<E>(ctx.effects, effect_environment)) {
      color3 background = eval_environment(lights, normalize(ray.direction));
      float weight = 1;
      // The environment has a selection slot only when it exists (--effects=all can switch
      // the effect on for a scene without one).
      if (LightSampling && !path.specular_bounce && lights.has_environment()) {
        float light_pdf =
            light_choice_probability(lights, path.previous_choice.position, path.previous_choice.normal,
                                     lights.environment_slot()) *
            environment_pdf(lights, path.previous_normal, normalize(ray.direction));
        weight = power_heuristic(path.previous_pdf, light_pdf);
      }
      radiance += clamp_contribution(ctx, throughput * background * weight, depth - 1);
    }
    return false;
  }
  // Only the light BVH rates lights by where they are seen from.
  LightChoicePoint here{};
  if (LightSampling && lights.sampler == LightSampler::bvh) here = light_choice_point(*ctx.accel, ray, id);
  if (SharesFirstVertex && depth == 0) {
    if (!path.gathers_first_vertex && shared->owner == path.sample)
      return scatter_shared(ctx, path, *shared, here, drawn, light, counts);
    if (path.gathers_first_vertex) shared->owner = nullptr;
  }
  SurfaceHit hit = make_surface_hit(*ctx.accel, ray, id);
  const SurfaceMaterial& m = material_at<E>(ctx, id, hit, scratch.resolved, texture_footprint_scale(sample.index));
  if (enabled<E>(ctx.effects, effect_alpha) && m.opacity < 1 &&
      // Each see-through step at this vertex gets its own dimension, far above any vertex's block.
      sample_1d(sample, dimension(depth, alpha_choice) + 0x10000u * uint32_t(path.transparent_steps)) >=
          m.opacity) {
    spawn_ray(path.ray, hit, ray.direction);  // see-through: the path goes on unchanged
    return ++path.transparent_steps < max_see_through_steps;
  }
  HitShading f = make_hit_shading<E>(ctx.effects, hit, m, ray.direction);
  if (path.first_hit && depth == 0) *path.first_hit = {bsdf_albedo(m), f.normal, id.t * length(ray.direction), 1};

  if (gathers && enabled<E>(ctx.effects, effect_emission) && !is_black(m.emission)) {
    const MaterialDesc& authored = ctx.scene->materials[hit.material];
    if (hit.front_face || authored.double_sided) {
      float weight = 1;
      int light_index = hit_light_index(lights, id);
      if (LightSampling && !path.specular_bounce && light_index >= 0) {
        const AreaLight& light = lights.area_lights[light_index - lights.delta_lights.size()];
        float light_pdf =
            light_choice_probability(lights, path.previous_choice.position, path.previous_choice.normal,
                                     size_t(light_index)) *
            area_light_pdf(light, path.previous_position, hit.position, hit.geometric_normal);
        weight = power_heuristic(path.previous_pdf, light_pdf);
      }
      radiance += clamp_contribution(ctx, throughput * m.emission * weight, depth - 1);
    }
  }
  if (m.unlit) {
    if (gathers) radiance += clamp_contribution(ctx, throughput * m.base_color, depth - 1);
    return false;
  }
  // Vertex `depth` gathers light only below max_depth; the emission above completed the
  // direct light of the previous vertex.
  if (depth >= path.max_depth) return false;
  bool dispersive = enabled<E>(ctx.effects, effect_refraction) && m.dispersion > 0 && m.transmission > 0 &&
                    m.model == MaterialModel::metallic_roughness;
  vec3 normal = bsdf_normal(m, f);
  Bsdf bsdf = dispersive ? Bsdf(dispersive_material(m, sample_1d(sample, dimension(depth, dispersion_channel)),
                                                    path.channel, throughput, scratch.dispersed),
                                normal, f.wo, anisotropy_tangent(hit, m, normal),
                                enabled<E>(ctx.effects, effect_normal_maps) ? clearcoat_normal(hit, m, normal) : vec3{})
                         : bsdf_at<E>(ctx, hit, m, normal, f.wo);
  // A dispersive first vertex changes each sub-path's throughput and channel: not shared.
  if (SharesFirstVertex && depth == 0 && path.gathers_first_vertex && !dispersive)
    share_first_vertex(path, hit, m, f, bsdf, scratch, *shared);
  return scatter(ctx, path, hit, m, f, bsdf, here, drawn, light, counts);
}

template <uint32_t E, bool LightSampling>
inline void PathVariant<E, LightSampling>::share_first_vertex(const PathState& path, const SurfaceHit& hit, const SurfaceMaterial& m,
                               const HitShading& f, const Bsdf& bsdf, const VertexScratch& scratch,
                               SharedFirstVertex& shared) {
  shared.hit = hit;
  shared.material = &m;
  if (&m == &scratch.resolved) shared.material = &(shared.resolved = m);
  shared.shading = f;
  shared.bsdf = bsdf;
  shared.owner = path.sample;
}

// A sub-path at its camera sample's shared first vertex. A function of its own, so that the
// batch's loop inlines one copy of scatter for both.
template <uint32_t E, bool LightSampling>
[[gnu::noinline]] bool PathVariant<E, LightSampling>::scatter_shared(const RenderContext& ctx, PathState& path,
                                             const SharedFirstVertex& shared, const LightChoicePoint& here,
                                             VertexDraws* drawn, LightSampleResult& light, RayCounts& counts) {
  return scatter(ctx, path, shared.hit, *shared.material, shared.shading, *shared.bsdf, here, drawn, light, counts);
}

// The rest of a vertex once its hit is shaded: the bounce drawn, the light sample taken (by
// the path that gathers this vertex's light) and the next ray set.
template <uint32_t E, bool LightSampling>
[[gnu::always_inline]] inline bool PathVariant<E, LightSampling>::scatter(const RenderContext& ctx, PathState& path, const SurfaceHit& hit,
                                           const SurfaceMaterial& m, const HitShading& f, const Bsdf& bsdf,
                                           const LightChoicePoint& here, VertexDraws* drawn,
                                           LightSampleResult& light, RayCounts& counts) {
  int depth = path.depth;
  const SampleContext& sample = depth == 0 ? *path.sample : path.own;
  color3& throughput = path.throughput;
  bool gathers = depth > 0 || path.gathers_first_vertex;
  // The next direction is drawn before the light sample, which does not depend on it: its
  // chain of dependent arithmetic (sampler, warp) then overlaps the shadow ray's traversal
  // in the CPU instead of stalling the next ray. Dimensions are fixed, so the order changes
  // no value.
  float u_lobe = 0.5f;
  if (bsdf.chooses_lobe()) {
    if (drawn) drawn->lobe_choice_used = true;
    u_lobe = drawn && drawn->has(lobe_choice) ? drawn->lobe_choice : sample_1d(path.own, dimension(depth, lobe_choice));
  }
  auto scattered = drawn && drawn->has(bsdf_direction)
                       ? bsdf.sample(u_lobe, drawn->direction, drawn->cosine)
                       : bsdf.sample(u_lobe, sample_2d(path.own, dimension(depth, bsdf_direction)));
  if (LightSampling && gathers && !is_pure_delta(m)) {
    sample_one_light<E>(ctx, hit, bsdf, f, here, sample, depth, drawn, counts, light);
    if (light.traces) {
      light.unblocked = clamp_contribution(ctx, throughput * light.unblocked, depth);
      light.blocked = clamp_contribution(ctx, throughput * light.blocked, depth);
    } else {
      path.radiance += clamp_contribution(ctx, throughput * light.unblocked, depth);
    }
  }
  if (!scattered || is_black(scattered->weight)) return false;
  // Without indirect light a diffuse or glossy bounce only completes this vertex's direct light.
  if (!scattered->delta && !enabled<E>(ctx.effects, effect_indirect))
    path.max_depth = std::min(path.max_depth, depth + 1);
  if (scattered->delta) {
    bool refracted = scattered->transmitted;
    if (refracted && !enabled<E>(ctx.effects, effect_refraction)) return false;
    // A transmissive surface's mirror share (Fresnel, total internal reflection) belongs to
    // refraction: switching reflection off must not make glass lose it.
    bool transmissive = !is_black(m.kt) || m.transmission > 0;
    if (!refracted && !transmissive && !enabled<E>(ctx.effects, effect_reflection)) return false;
    path.ray_kind = refracted ? &RayCounts::refraction : &RayCounts::reflection;
  } else {
    path.ray_kind = &RayCounts::indirect;
  }
  // Crossing a surface enters its volume from the front and leaves it from the back.
  if (enabled<E>(ctx.effects, effect_absorption) && scattered->transmitted)
    path.medium = hit.front_face && !is_black(ctx.absorption[size_t(hit.material)]) ? hit.material : -1;
  throughput *= depth == 0 ? scattered->weight * path.split_weight : scattered->weight;
  path.specular_bounce = scattered->delta;
  path.previous_pdf = scattered->pdf;
  path.previous_position = hit.position;
  path.previous_normal = f.normal;
  if (LightSampling && ctx.lights->sampler == LightSampler::bvh) path.previous_choice = here;
  spawn_ray(path.ray, hit, scattered->wi);
  path.depth = ++depth;
  if (depth >= roulette_start_depth) {
    // A sub-path's share (split_weight) is not a loss of light: roulette goes by its whole.
    float survive = std::min(1.0f, max_component(throughput) * path.split);
    float u = drawn && drawn->has(roulette) ? drawn->roulette : sample_1d(path.own, dimension(depth, roulette));
    if (u >= survive) return false;
    throughput /= survive;
  }
  return true;
}

// Sub-path `sub_path` of a camera sample at its camera ray, set field by field in place (see
// sample_one_light): the batch's workspace reuses its states. AOV values come from the first.
// Not inlined: in the batch's loop over camera samples GCC's -O3 loop distribution split its
// two dozen stores into as many loops, each walking all the path states for one field (about
// 100 instructions a camera sample of loop control, and the states streamed 28 times).
template <uint32_t E, bool LightSampling>
[[gnu::noinline]] void PathVariant<E, LightSampling>::start(PathState& path, const RenderContext& ctx, const Ray& camera_ray,
                                    const SampleContext& sample, int sub_path, FirstHit* first_hit) {
  path.radiance = {};
  path.throughput = {1, 1, 1};
  path.ray_kind = &RayCounts::camera;
  path.specular_bounce = true;
  path.previous_pdf = 0;
  path.depth = 0;
  path.transparent_steps = 0;
  path.medium = -1;
  path.channel = -1;
  path.ray.origin = camera_ray.origin;
  path.ray.direction = camera_ray.direction;
  path.ray.tmax = camera_ray.tmax;
  path.ray.time = camera_ray.time;
  path.sample = &sample;
  // One aggregate: copied and then given its index in a second store, GCC 12 at -O3 (not -O2,
  // nor with -fno-strict-aliasing) lost the index store in the batch's inlined copy, and every
  // sub-path drew the first one's numbers (tests/render/indirect_paths_test.cpp catches it).
  path.own = {sample.kind, sample.pixel, sample.index * uint32_t(ctx.split) + uint32_t(sub_path), sample.samples,
              sample.seed};
  path.gathers_first_vertex = sub_path == 0;
  path.split = float(ctx.split);
  path.split_weight = 1.0f / float(ctx.split);
  path.first_hit = sub_path == 0 ? first_hit : nullptr;
  path.max_depth = ctx.max_depth;
}

// A light sample's contribution past see-through occluders, its shadow ray's first segment
// traced to `first` (invalid: nothing in between).
template <uint32_t E, bool LightSampling>
inline color3 PathVariant<E, LightSampling>::light_past(const RenderContext& ctx, const LightSampleResult& light, const HitId& first,
                         RayCounts& counts) {
  return light.unblocked *
         transmittance_past<E>(ctx, light.shadow_ray, first, light.target, false, light.footprint_scale, counts);
}

// One path at a time (its sub-paths one after another, summed in order, each shading the first
// vertex itself): the reference the batch must match.
template <uint32_t E, bool LightSampling>
inline color3 PathVariant<E, LightSampling>::run(const RenderContext& ctx, const Ray& camera_ray, const SampleContext& sample, RayCounts& counts,
                  FirstHit* first_hit, const HitId* camera_hit) {
  ++counts.camera;
  HitId first = camera_hit ? *camera_hit : intersect_nearest(*ctx.accel, camera_ray, camera_culling(ctx));
  VertexScratch scratch;
  LightSampleResult light;
  color3 sum;
  for (int sub_path = 0; sub_path < ctx.split; ++sub_path) {
    PathState path;
    start(path, ctx, camera_ray, sample, sub_path, first_hit);
    HitId id = first;
    for (;;) {
      bool goes_on = advance<false>(ctx, path, id, nullptr, scratch, nullptr, light, counts);
      if (light.traces)
        path.radiance += shadows_are_opaque<E>(ctx)
                             ? (is_occluded(*ctx.accel, light.shadow_ray) ? light.blocked : light.unblocked)
                             : light_past(ctx, light, intersect_nearest(*ctx.accel, light.shadow_ray), counts);
      if (!goes_on) break;
      ++(counts.*path.ray_kind);
      id = intersect_nearest(*ctx.accel, path.ray, culling_of(ctx, path));
    }
    sum = sub_path == 0 ? path.radiance : sum + path.radiance;
  }
  return sum;
}

}  // namespace

}  // namespace radiant
