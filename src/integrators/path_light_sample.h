// Next-event estimation for the path integrator: one light sample with MIS against BSDF
// sampling, its shadow ray left to the caller, and the emission of the light a path hits.
#pragma once

#include <algorithm>
#include <cmath>

#include "integrators/background.h"
#include "integrators/hit_shading.h"
#include "integrators/light_choice_point.h"
#include "integrators/naive.h"
#include "integrators/path_sample_dimensions.h"
#include "integrators/sample_clamp.h"
#include "integrators/shadow.h"
#include "integrators/surface_lanes.h"
#include "lights/area_light.h"
#include "lights/delta_light.h"
#include "lights/environment_light.h"
#include "lights/light_selection.h"
#include "materials/bsdf.h"
#include "materials/dispersion.h"
#include "sampling/cosine_warp.h"
#include "sampling/sampler.h"
#include "sampling/warp.h"

namespace radiant {

// Internal to the path integrator: included by path.cpp alone.
namespace {

// Emission of an area light at a sampled point (textured emission looked up from the mesh).
template <uint32_t E>
color3 area_light_emission(const RenderContext& ctx, const AreaLight& light, vec2 barycentric) {
  const MaterialDesc& material = ctx.scene->materials[light.material];
  if (!enabled<E>(ctx.effects, effect_textures) || !material.emission_texture.valid() || light.instance < 0)
    return ctx.flat_materials[light.material].emission;
  const MeshDesc& mesh = ctx.scene->meshes[ctx.scene->instances[light.instance].mesh];
  SurfaceAttributes attributes;
  const uint32_t* tri = &mesh.indices[size_t(light.primitive) * 3];
  float b0 = 1 - barycentric.x - barycentric.y;
  for (int set = 0; set < 2; ++set) {
    const auto& uvs = set == 0 ? mesh.texcoords0 : mesh.texcoords1;
    if (!uvs.empty()) attributes.uv[set] = uvs[tri[0]] * b0 + uvs[tri[1]] * barycentric.x + uvs[tri[2]] * barycentric.y;
  }
  return resolve_material(*ctx.scene, material, attributes).emission;
}

// Index in the light table of the area light that was hit, or -1.
int hit_light_index(const LightTable& lights, const HitId& id) {
  int area = -1;
  if (id.instance >= 0 && !lights.instance_light_base.empty() && lights.instance_light_base[id.instance] >= 0)
    area = lights.instance_light_base[id.instance] + int(id.primitive);
  else if (id.shape >= 0 && !lights.shape_light.empty())
    area = lights.shape_light[id.shape];
  return area < 0 ? -1 : int(lights.delta_lights.size()) + area;
}

// One light sample's contribution (sample_one_light leaves it before the path's throughput,
// advance scales it). Its shadow ray is left to the caller (`traces`), who may trace it with
// others (the batch traces a stage's together). With opaque shadows the contribution is then `unblocked` or
// `blocked` by the ray's answer; with see-through occluders it is `unblocked` times the light
// let through past them (transmittance_past, walking on towards `target`). Without `traces`,
// `unblocked` is final.
struct LightSampleResult {
  color3 unblocked, blocked;
  Ray shadow_ray;
  // See-through occluders only: where the shadow ray ends (shadow_target), and the vertex's
  // texture footprint scale, for the occluders' textures.
  vec3 target;
  float footprint_scale;
  bool traces = false;
};

// One light sample with MIS against BSDF sampling (next-event estimation) into `out`, as a
// contribution before the path's throughput. `out` is written in place: built elsewhere and
// copied, its ray would stall on store forwarding.
template <uint32_t E>
[[gnu::always_inline]] inline void sample_one_light(const RenderContext& ctx, const SurfaceHit& hit, const Bsdf& bsdf,
                                                    const HitShading& f, const LightChoicePoint& here,
                                                    const SampleContext& sample, int depth, const VertexDraws* drawn,
                                                    RayCounts& counts, LightSampleResult& out) {
  out.traces = false;
  out.unblocked = {};
  const LightTable& lights = *ctx.lights;
  // Random numbers are drawn only when used (one light needs no choice, a delta light no
  // point); their dimensions stay fixed, so skipping one changes no other.
  LightChoice choice;
  auto u_choice = [&] {
    return drawn && drawn->has(light_choice) ? drawn->light_choice : sample_1d(sample, dimension(depth, light_choice));
  };
  auto u_light_point = [&] {
    return drawn && drawn->has(light_point) ? drawn->light_point : sample_2d(sample, dimension(depth, light_point));
  };
  if (drawn && drawn->light_chosen) {
    if (!drawn->light_found) return;
    choice = {drawn->light_slot, drawn->light_probability};
  } else if (!choose_light(lights, here.position, here.normal, u_choice, choice)) {
    return;
  }
  size_t index = choice.slot;
  float select_pdf = choice.probability;

  // The contribution for the shadow ray's transmittance `t`; with opaque shadows both answers
  // are formed now, so that the caller's choice is the value the transmittance would give. Past
  // see-through occluders the caller multiplies the unblocked one by what they let through.
  // `direction` by reference: by value, it came in registers, and the call stored it and read
  // it back as an 8-byte block across two stores, which the CPU cannot forward (a third of the
  // call's time).
  auto finish = [&](const vec3& direction, float distance, auto contribution) {
    out.unblocked = contribution(color3{1, 1, 1});
    if (!enabled<E>(ctx.effects, effect_shadows)) return;
    counts.shadow++;
    if (shadows_are_opaque<E>(ctx))
      out.blocked = contribution(color3{0, 0, 0});
    else
      out.target = shadow_target(hit, direction, distance), out.footprint_scale = texture_footprint_scale(sample.index);
    set_shadow_ray(out.shadow_ray, hit, direction, distance);
    out.traces = true;
  };

  if (index < lights.delta_lights.size()) {
    if (!enabled<E>(ctx.effects, effect_direct_delta)) return;
    DeltaLightSample light;
    if (!sample_delta_light(ctx.scene->lights[lights.delta_lights[index]], hit.position, light)) return;
    color3 f_cos = bsdf.eval(light.direction);
    if (is_black(f_cos)) return;
    return finish(light.direction, light.distance, [&](color3 t) {
      if (is_black(t)) return color3{};
      return f_cos * light.irradiance * t / select_pdf;
    });
  }

  vec3 wi;
  float light_pdf;
  color3 emitted;
  float distance;
  if (index < lights.environment_slot()) {
    if (!enabled<E>(ctx.effects, effect_emission)) return;
    const AreaLight& light = lights.area_lights[index - lights.delta_lights.size()];
    AreaLightSample s;
    vec2 u_point = u_light_point();
    if (!sample_area_light(light, hit.position, u_point, s)) return;
    if (!area_light_emits(light, s.normal, -s.direction)) return;
    wi = s.direction;
    light_pdf = s.pdf;
    distance = s.distance * (1 - 1e-4f);
    emitted = area_light_emission<E>(ctx, light, s.barycentric);
  } else {
    if (!enabled<E>(ctx.effects, effect_environment)) return;
    float u_environment = sample_1d(sample, dimension(depth, environment_choice));
    light_pdf = sample_environment(lights, f.normal, u_environment, u_light_point(), wi);
    if (!(light_pdf > 0)) return;
    distance = std::numeric_limits<float>::infinity();
    emitted = eval_environment(lights, wi);
  }
  if (is_black(emitted)) return;
  float bsdf_pdf;
  color3 f_cos = bsdf.eval(wi, bsdf_pdf);
  if (is_black(f_cos)) return;
  float pdf = select_pdf * light_pdf;
  float weight = power_heuristic(pdf, bsdf_pdf);
  finish(wi, distance, [&](color3 t) {
    if (is_black(t)) return color3{};
    return f_cos * emitted * t * (weight / pdf);
  });
}

}  // namespace

}  // namespace radiant
