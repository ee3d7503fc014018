// A surface lane's light sample: delta lights and emitting triangles in SIMD lanes (the light
// samplers' formulas, lights/), its MIS against the lane's BSDF, and its shadow ray.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "accel/ray.h"
#include "integrators/surface_lane_bsdfs.h"
#include "lights/delta_light.h"
#include "math/lane.h"
#include "sampling/warp.h"

namespace radiant {

// Internal to the surface lanes: included by surface_lanes.cpp alone, after surface_lanes.h
// (SurfaceLanes), whose unit these files are part of.
namespace {

using lane::largest_float;
using lane::normalize_in_range;
using lane::select;

// What a light sample leaves for its shadow ray: the direction to the light, how far the ray
// goes, the contribution before the throughput, whether there is one, and the BSDF's in_range.
struct LaneLight {
  vec3 direction;
  float distance;
  color3 contribution;
  bool lit;
  bool in_range;
};

// A point light without range (delta_light.h, sample_delta_light) and its contribution
// (path_light_sample.h, sample_one_light). `eval(direction)` is the BSDF's LaneBsdfValue (LambertValue or
// GlossyValue: a lambda's call GCC may leave out of line, and the loop is then not vectorised).
template <class Eval>
[[gnu::always_inline]] inline LaneLight point_light_lane(const SurfaceLanes& l, int i, vec3 point, Eval eval) {
  LaneLight s;
  vec3 to_light = vec3{l.light_x[i], l.light_y[i], l.light_z[i]} - point;
  float d = length(to_light);
  s.direction = to_light * (1 / d);
  s.distance = d;
  float attenuation = point_light_attenuation(l.kc[i], l.kl[i], l.kq[i], d);
  color3 irradiance = color3{l.intensity_r[i], l.intensity_g[i], l.intensity_b[i]} * (1.0f / attenuation);
  LaneBsdfValue bsdf = eval(s.direction);
  s.lit = (d > 0) & (attenuation > 0) & bsdf.nonzero;
  s.in_range = bsdf.in_range;
  s.contribution = bsdf.f_cos * irradiance * color3{1, 1, 1} / l.select_pdf[i];
  return s;
}

// Any delta light (delta_light.cpp, sample_any_delta_light): a point light with the glTF spot's
// smooth cone or a classic spot's power of the cosine (spot_powers) and the glTF range's window
// where it has them, or a directional light. The point light's own numbers where it has
// neither: falloff 1 divided by the attenuation is 1 / attenuation to the bit.
template <class Eval>
[[gnu::always_inline]] inline LaneLight shaped_delta_light_lane(const SurfaceLanes& l, int i, vec3 point, Eval eval) {
  LaneLight s;
  vec3 to_light = vec3{l.light_x[i], l.light_y[i], l.light_z[i]} - point;
  float d = length(to_light);
  vec3 towards = to_light * (1 / d);
  float attenuation = point_light_attenuation(l.kc[i], l.kl[i], l.kq[i], d);
  vec3 axis = {l.spot_x[i], l.spot_y[i], l.spot_z[i]};
  float cone = smooth_cone_falloff(dot(axis, -towards), {l.cos_outer[i], l.cone_scale[i]});
  float falloff = l.spot[i] != 0 ? cone : 1.0f;
  float spot_power = l.spot_power[i];  // loaded in every lane: a conditional load kept the loop scalar
  falloff = l.classic_spot[i] != 0 ? spot_power : falloff;
  float window = range_window(d, l.range[i]);
  falloff = l.range[i] > 0 ? falloff * window : falloff;
  color3 intensity = {l.intensity_r[i], l.intensity_g[i], l.intensity_b[i]};
  bool directional = l.directional[i] != 0;
  s.direction = lane::select_bits(directional, -axis, towards);
  s.distance = directional ? std::numeric_limits<float>::infinity() : d;
  color3 irradiance = lane::select_bits(directional, intensity, intensity * (falloff / attenuation));
  LaneBsdfValue bsdf = eval(s.direction);
  s.lit = (directional | ((d > 0) & (attenuation > 0) & (falloff > 0))) & bsdf.nonzero;
  s.in_range = bsdf.in_range;
  s.contribution = bsdf.f_cos * irradiance * color3{1, 1, 1} / l.select_pdf[i];
  return s;
}

// An emitting triangle (area_light.cpp, sample_area_light and area_light_emits; Heitz's
// mapping of sample_uniform_triangle) and its contribution with MIS against the BSDF's sampling.
template <class Eval>
[[gnu::always_inline]] inline LaneLight triangle_light_lane(const SurfaceLanes& l, int i, vec3 point, Eval eval) {
  LaneLight s;
  vec2 b = sample_uniform_triangle({l.u_point_x[i], l.u_point_y[i]});
  vec3 position = vec3{l.light_x[i], l.light_y[i], l.light_z[i]} * (1 - b.x - b.y) +
                  vec3{l.light1_x[i], l.light1_y[i], l.light1_z[i]} * b.x +
                  vec3{l.light2_x[i], l.light2_y[i], l.light2_z[i]} * b.y;
  vec3 light_normal = {l.light_nx[i], l.light_ny[i], l.light_nz[i]};
  vec3 to_light = position - point;
  float d = length(to_light);
  s.direction = to_light / d;
  float area = l.light_area[i];
  float cos_light = std::abs(dot(light_normal, s.direction));
  float light_pdf = d * d / (area * cos_light);
  bool emits = (l.two_sided[i] != 0) | (dot(light_normal, -s.direction) > 0);
  color3 emitted = {l.intensity_r[i], l.intensity_g[i], l.intensity_b[i]};
  LaneBsdfValue bsdf = eval(s.direction);
  float pdf = l.select_pdf[i] * light_pdf;
  float weight = power_heuristic(pdf, bsdf.pdf);
  s.distance = d * (1 - 1e-4f);
  s.lit = (d > 0) & (area > 0) & (cos_light > 1e-7f) & (std::abs(light_pdf) <= largest_float) & emits &
          !lane::black(emitted) & bsdf.nonzero;
  s.contribution = bsdf.f_cos * emitted * color3{1, 1, 1} * (weight / pdf);
  s.in_range = bsdf.in_range;
  return s;
}

// A light sample's outputs: whether it lights the point, its contribution through the
// throughput, and its shadow ray (as set_shadow_ray: spawn_ray_to towards the light, or with
// `MayBeInfinite` and an infinite distance, spawn_ray along the direction) with the point it
// ends at (shadow_target's, for a walk past see-through occluders; any value when infinite).
struct LightOutputs {
  int32_t lit;
  color3 contribution;
  vec3 shadow_origin, shadow_direction, shadow_target;
  int32_t infinite = 0;
};
template <bool MayBeInfinite = false>
[[gnu::always_inline]] inline LightOutputs light_outputs(const SurfaceLanes& l, int i, const LaneLight& light,
                                                         vec3 point, vec3 error, vec3 geometric_normal) {
  LightOutputs o;
  o.lit = light.lit;
  o.contribution = color3{l.throughput_r[i], l.throughput_g[i], l.throughput_b[i]} * light.contribution;
  vec3 target = point + light.direction * light.distance;
  o.shadow_target = target;
  if constexpr (MayBeInfinite) {
    bool infinite = !(light.distance <= largest_float);
    o.shadow_origin = offset_ray_origin(point, error, geometric_normal, lane::select_bits(infinite, light.direction, target - point));
    o.shadow_direction = lane::select_bits(infinite, light.direction, target - o.shadow_origin);
    o.infinite = infinite;
  } else {
    o.shadow_origin = offset_ray_origin(point, error, geometric_normal, target - point);
    o.shadow_direction = target - o.shadow_origin;
  }
  return o;
}
[[gnu::always_inline]] inline LightOutputs stored_light_outputs(const SurfaceLanes& l, int i) {
  return {l.lit[i], {l.light_r[i], l.light_g[i], l.light_b[i]}, {l.shadow_ox[i], l.shadow_oy[i], l.shadow_oz[i]},
          {l.shadow_dx[i], l.shadow_dy[i], l.shadow_dz[i]}, {l.shadow_tx[i], l.shadow_ty[i], l.shadow_tz[i]},
          l.shadow_infinite[i]};
}
[[gnu::always_inline]] inline void store_light_outputs(SurfaceLanes& l, int i, const LightOutputs& o) {
  l.lit[i] = o.lit;
  l.light_r[i] = o.contribution.x, l.light_g[i] = o.contribution.y, l.light_b[i] = o.contribution.z;
  l.shadow_ox[i] = o.shadow_origin.x, l.shadow_oy[i] = o.shadow_origin.y, l.shadow_oz[i] = o.shadow_origin.z;
  l.shadow_dx[i] = o.shadow_direction.x, l.shadow_dy[i] = o.shadow_direction.y, l.shadow_dz[i] = o.shadow_direction.z;
  l.shadow_tx[i] = o.shadow_target.x, l.shadow_ty[i] = o.shadow_target.y, l.shadow_tz[i] = o.shadow_target.z;
  l.shadow_infinite[i] = o.infinite;
}
// Where `replaces`, the outputs `o` of a later light loop; elsewhere what the lane had. Stored
// in every lane: a conditional store is a branch without AVX2's masked stores.
[[gnu::always_inline]] inline void store_light_outputs_where(SurfaceLanes& l, int i, bool replaces, LightOutputs o) {
  LightOutputs kept = stored_light_outputs(l, i);
  o.lit = replaces ? o.lit : kept.lit;
  o.contribution = select(replaces, o.contribution, kept.contribution);
  o.shadow_origin = select(replaces, o.shadow_origin, kept.shadow_origin);
  o.shadow_direction = select(replaces, o.shadow_direction, kept.shadow_direction);
  o.shadow_target = select(replaces, o.shadow_target, kept.shadow_target);
  o.infinite = replaces ? o.infinite : kept.infinite;
  store_light_outputs(l, i, o);
}

}  // namespace

}  // namespace radiant
