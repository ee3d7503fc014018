#include "integrators/surface_lanes.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "accel/ray.h"
#include "accel/triangle_point.h"
#include "lights/area_light.h"
#include "lights/environment_light.h"
#include "materials/bsdf_models.h"
#include "materials/metallic_roughness_lane.h"
#include "materials/microfacet.h"
#include "materials/shading_frame.h"
#include "math/dvec3.h"
#include "sampling/warp.h"

namespace radiant {

namespace {

using lane::largest_float;
using lane::normalize_in_range;
using lane::select;

// A BSDF's value towards a light: f * |cos|, the pdf its sampling gives the direction, whether
// the light sample goes on (the one-path code's test that f is not black), and false in
// `in_range` where the lane must fall back.
struct LaneBsdfValue {
  color3 f_cos;
  float pdf;
  bool nonzero;
  bool in_range = true;
};

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
// (path.cpp, sample_one_light). `eval(direction)` is the BSDF's LaneBsdfValue (LambertValue or
// GlossyValue: a lambda's call GCC may leave out of line, and the loop is then not vectorised).
template <class Eval>
[[gnu::always_inline]] inline LaneLight point_light_lane(const SurfaceLanes& l, int i, vec3 point, Eval eval) {
  LaneLight s;
  vec3 to_light = vec3{l.light_x[i], l.light_y[i], l.light_z[i]} - point;
  float d = length(to_light);
  s.direction = to_light * (1 / d);
  s.distance = d;
  float attenuation = l.kc[i] + l.kl[i] * d + l.kq[i] * d * d;
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
  float attenuation = l.kc[i] + l.kl[i] * d + l.kq[i] * d * d;
  vec3 axis = {l.spot_x[i], l.spot_y[i], l.spot_z[i]};
  float t = std::clamp((dot(axis, -towards) - l.cos_outer[i]) * l.cone_scale[i], 0.0f, 1.0f);
  float falloff = l.spot[i] != 0 ? t * t : 1.0f;
  float spot_power = l.spot_power[i];  // loaded in every lane: a conditional load kept the loop scalar
  falloff = l.classic_spot[i] != 0 ? spot_power : falloff;
  float r = d / l.range[i];
  float window = std::clamp(1 - r * r * r * r, 0.0f, 1.0f);
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

// The Lambert lobes' value towards `wi` (eval_world), `normal` facing wo.
struct LambertValue {
  vec3 normal;
  color3 albedo;
  bool valid;
  [[gnu::always_inline]] LaneBsdfValue operator()(vec3 wi) const {
    float cos_i = dot(normal, wi);
    color3 f_cos = albedo * (inv_pi * cos_i);
    return {f_cos, cos_i * inv_pi, bool(valid & (cos_i >= lambert_min_cosine) & !lane::black(f_cos))};
  }
};

// A glossy lane's material and its lobes as the first loop left them.
[[gnu::always_inline]] inline GlossyLaneMaterial glossy_material(const SurfaceLanes& l, int i) {
  return {{l.albedo_r[i], l.albedo_g[i], l.albedo_b[i]},
          l.alpha[i],
          l.ior[i],
          l.ior_f0[i],
          l.metal[i],
          l.plastic[i],
          l.specular[i],
          {l.specular_f0_r[i], l.specular_f0_g[i], l.specular_f0_b[i]},
          {l.albedo_roughness[i], l.albedo_ior[i],
           {l.multiple_r[i], l.multiple_g[i], l.multiple_b[i]}, l.multiple_normalization[i],
           l.coating_reflect[i], l.coating_rise[i], l.coating_multiple[i], l.diffuse_normalization[i]}};
}
[[gnu::always_inline]] inline GlossyLaneLobes stored_glossy_lobes(const SurfaceLanes& l, int i) {
  return {{l.lobe_nx[i], l.lobe_ny[i], l.lobe_nz[i]},
          {l.wo_x[i], l.wo_y[i], l.wo_z[i]},
          l.p_specular[i],
          l.p_diffuse[i],
          l.coating_o[i],
          l.loss_o[i],
          l.lambda_o[i],
          l.valid[i] != 0};
}
// The metallic-roughness lobes' value towards the world direction `wi` (Bsdf::eval_framed),
// the albedo tables' values there looked up ahead (GlossyRecord, glossy_light_albedos).
template <bool WithPdf>
struct GlossyValue {
  GlossyLaneMaterial m;
  GlossyLaneLobes lobes;
  MicrofacetAlbedos at_i;
  [[gnu::always_inline]] LaneBsdfValue operator()(vec3 wi) const {
    float pdf = 0;
    bool in_range;
    color3 f = eval_glossy_lane<WithPdf>(m, lobes, to_local(make_shading_frame(lobes.normal), wi), at_i, pdf, in_range);
    return {f, pdf, !lane::black(f), in_range};
  }
};
// In a light loop's first pass over glossy lanes: records the local cosine of the light's
// direction into `cosine`, for glossy_light_albedos; the pass's light sample is discarded.
struct GlossyRecord {
  vec3 normal;  // the lobes' frame's z
  float* cosine;
  [[gnu::always_inline]] LaneBsdfValue operator()(vec3 wi) const {
    *cosine = to_local(make_shading_frame(normal), wi).z;
    return {{0, 0, 0}, 0, false};
  }
};

// A Phong lane's lobes (phong_bsdf.cpp, make_phong_lobes: facing_frame without a tangent).
struct PhongLaneLobes {
  vec3 normal;  // the frame's z: the shading normal on wo's side
  vec3 wo;      // local
  bool valid;
};
[[gnu::always_inline]] inline PhongLaneLobes make_phong_lane_lobes(vec3 n, vec3 wo) {
  PhongLaneLobes lobes;
  lobes.normal = select(dot(n, wo) < 0, -n, n);
  lobes.wo = to_local(make_shading_frame(lobes.normal), wo);
  lobes.valid = (lobes.wo.z > 1e-7f) & lane::finite(lobes.wo);  // a lane material always scatters
  return lobes;
}
[[gnu::always_inline]] inline PhongLaneLobes stored_phong_lobes(const SurfaceLanes& l, int i) {
  return {{l.lobe_nx[i], l.lobe_ny[i], l.lobe_nz[i]}, {l.wo_x[i], l.wo_y[i], l.wo_z[i]}, l.valid[i] != 0};
}
// The cosine phong_lobe raises to the exponent: between local `wi` and the mirror of wo.
[[gnu::always_inline]] inline float phong_cosine(const PhongLaneLobes& lobes, vec3 wi) {
  return dot(wi, reflect_local(lobes.wo));
}
// A Phong lane's eval_local and pdf_local at a local direction whose lobe power (cos^n,
// phong_lobe_power) is `power`.
[[gnu::always_inline]] inline color3 eval_phong_lane(const SurfaceLanes& l, int i, const PhongLaneLobes& lobes,
                                                     vec3 wi, float power, float& pdf) {
  bool in = lobes.valid & !(wi.z < 1e-7f);
  color3 kd = {l.albedo_r[i], l.albedo_g[i], l.albedo_b[i]}, ks = {l.ks_r[i], l.ks_g[i], l.ks_b[i]};
  float exponent = l.exponent[i], p_diffuse = l.p_diffuse[i], p_glossy = l.p_specular[i];
  color3 f = kd * inv_pi;
  f = select(p_glossy > 0, f + ks * ((exponent + 2) / (2 * pi) * power), f);
  f = f * wi.z;
  float diffuse_pdf = p_diffuse * wi.z * inv_pi;
  pdf = p_glossy > 0 ? diffuse_pdf + p_glossy * (exponent + 1) / (2 * pi) * power : diffuse_pdf;
  pdf = lane::zero_unless(in, pdf);
  return {lane::zero_unless(in, f.x), lane::zero_unless(in, f.y), lane::zero_unless(in, f.z)};
}
// The Phong lobes' value towards the world direction `wi` (Bsdf::eval_framed), the lobe power
// there worked out ahead (phong_power).
struct PhongValue {
  const SurfaceLanes& l;
  int i;
  PhongLaneLobes lobes;
  float power;
  [[gnu::always_inline]] LaneBsdfValue operator()(vec3 wi) const {
    float pdf;
    color3 f = eval_phong_lane(l, i, lobes, to_local(make_shading_frame(lobes.normal), wi), power, pdf);
    return {f, pdf, !lane::black(f)};
  }
};
// In a light loop's first pass over Phong lanes: records the cosine of the light's direction
// into `cosine`, for phong_powers to raise; the pass's light sample is discarded.
struct PhongRecord {
  PhongLaneLobes lobes;
  float* cosine;
  [[gnu::always_inline]] LaneBsdfValue operator()(vec3 wi) const {
    *cosine = phong_cosine(lobes, to_local(make_shading_frame(lobes.normal), wi));
    return {{0, 0, 0}, 0, false};
  }
};

// The BSDF a lane of model `Model` evaluates towards a light (a Phong lane's power at the light
// worked out ahead); `WithPdf` where the light's MIS needs the glossy lobes' pdf.
template <RenderContext::LaneModel Model, bool WithPdf>
[[gnu::always_inline]] inline auto lane_bsdf(const SurfaceLanes& l, int i) {
  using LaneModel = RenderContext::LaneModel;
  if constexpr (Model == LaneModel::glossy) {
    return GlossyValue<WithPdf>{glossy_material(l, i), stored_glossy_lobes(l, i), {l.albedo_i[i], l.rise_i[i]}};
  } else if constexpr (Model == LaneModel::phong) {
    return PhongValue{l, i, stored_phong_lobes(l, i), l.phong_power[i]};
  } else {
    return LambertValue{{l.lobe_nx[i], l.lobe_ny[i], l.lobe_nz[i]}, {l.albedo_r[i], l.albedo_g[i], l.albedo_b[i]},
                        l.valid[i] != 0};
  }
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

// A lane's instance transforms (surface_hit.cpp, fill_triangle_hit), as entries for the products
// of math/matrix_entries.h: to the world, and the inverse's 3x3 part for normals.
struct LaneToWorld {
  const SurfaceLanes& l;
  int i;
  [[gnu::always_inline]] float operator()(int r, int c) const { return l.to_world[r * 4 + c][i]; }
};
struct LaneToObject {
  const SurfaceLanes& l;
  int i;
  [[gnu::always_inline]] float operator()(int r, int c) const { return l.to_object[r * 3 + c][i]; }
};

// A sphere's or a plane's hit moved onto the surface in double precision, and its error bound
// (analytic_shapes.cpp, refine_shape_point, from fill_shape_hit's approximate point).
struct ShapePoint {
  vec3 point;
  float error;
};
[[gnu::always_inline]] inline ShapePoint refine_shape_lane(const SurfaceLanes& l, int i, vec3 direction) {
  vec3 approximate = vec3{l.ray_ox[i], l.ray_oy[i], l.ray_oz[i]} + direction * l.ray_t[i];
  dvec3 p = to_double(approximate), c = to_double({l.center_x[i], l.center_y[i], l.center_z[i]});
  float radius = l.radius[i];
  bool sphere = l.shape[i] == SurfaceLanes::sphere_hit;
  dvec3 local = p - c;
  double len = std::sqrt(dot(local, local));
  dvec3 on_sphere = c + local * (double(radius) / len);
  dvec3 n = to_double({l.axis_x[i], l.axis_y[i], l.axis_z[i]});
  dvec3 on_plane = p - n * dot(p - c, n);
  // Chosen after rounding to float, by 32-bit masks: SSE2 has no 64-bit compare to make double
  // masks from, and as ternaries GCC branches. len > 0 exactly when its float is: p and c are
  // floats, so a nonzero len is at least their smallest nonzero difference, a float.
  bool moves = float(len) > 0;
  vec3 sphere_point = lane::select_bits(moves, to_float(on_sphere), approximate);
  ShapePoint s;
  s.point = lane::select_bits(sphere, sphere_point, to_float(on_plane));
  s.error = max_component(abs(s.point)) * rounding_gamma(4);
  s.error = lane::select_bits(sphere, s.error + std::abs(radius) * rounding_gamma(4), s.error);
  return s;
}

// A lane's hit: make_surface_hit for a triangle (surface_hit.cpp, fill_triangle_hit) and
// make_hit_shading. `in_range` is false where a normalize() the one-path code does would have
// rescaled. `Hits`: which kinds of hit beside untransformed triangles the lanes hold
// (SurfaceLanes::hit_kinds), each decoded only where some lane needs it.
struct LaneHit {
  vec3 point;
  float error;  // the position's error bound, the same along every axis
  vec3 geometric_normal;
  vec3 normal;  // the shading normal facing the ray (HitShading::normal)
  vec3 wo;
  bool in_range;
};
template <int Hits>
[[gnu::always_inline]] inline LaneHit decode_lane(const SurfaceLanes& l, int i) {
  LaneHit hit;
  vec3 p0 = {l.p0x[i], l.p0y[i], l.p0z[i]}, p1 = {l.p1x[i], l.p1y[i], l.p1z[i]}, p2 = {l.p2x[i], l.p2y[i], l.p2z[i]};
  float b1 = l.b1[i], b2 = l.b2[i];
  vec3 direction = {l.dx[i], l.dy[i], l.dz[i]};
  vec3 e1 = p1 - p0, e2 = p2 - p0;
  TrianglePoint object = triangle_point(p0, e1, e2, b1, b2);
  // Untransformed, Embree's Ng; transformed, the object normal's image.
  vec3 geometric = {l.ngx[i], l.ngy[i], l.ngz[i]};
  bool transformed = false;
  hit.point = object.point;
  vec3 error = object.error;
  if constexpr ((Hits & SurfaceLanes::transformed_hits) != 0) {
    transformed = l.transformed[i] != 0;
    vec3 world_error = world_point_error(LaneToWorld{l, i}, object.point, object.error);
    hit.point = lane::select_bits(transformed, transform_point_by(LaneToWorld{l, i}, object.point), object.point);
    error = lane::select_bits(transformed, world_error, object.error);
    geometric = lane::select_bits(transformed, transform_normal_by(LaneToObject{l, i}, cross(e1, e2)), geometric);
  }
  hit.error = max_component(error);
  if constexpr ((Hits & SurfaceLanes::shape_hits) != 0) {
    bool shape = l.shape[i] != SurfaceLanes::triangle_hit;
    ShapePoint refined = refine_shape_lane(l, i, direction);
    hit.point = lane::select_bits(shape, refined.point, hit.point);
    hit.error = lane::select_bits(shape, refined.error, hit.error);
  }
  bool normal_in_range, direction_in_range;
  hit.geometric_normal = normalize_in_range(geometric, normal_in_range);
  if constexpr ((Hits & SurfaceLanes::transformed_hits) != 0)
    hit.geometric_normal = lane::select_bits(transformed, hit.geometric_normal * l.orientation[i], hit.geometric_normal);
  bool front_face = dot(direction, hit.geometric_normal) < 0;
  // Interpolated vertex normals, on the geometric normal's side, where they are usable.
  float b0 = 1 - b1 - b2;
  vec3 interpolated = barycentric_mix(vec3{l.n0x[i], l.n0y[i], l.n0z[i]}, vec3{l.n1x[i], l.n1y[i], l.n1z[i]},
                                      vec3{l.n2x[i], l.n2y[i], l.n2z[i]}, b0, b1, b2);
  if constexpr ((Hits & SurfaceLanes::transformed_hits) != 0)
    interpolated = lane::select_bits(transformed, transform_normal_by(LaneToObject{l, i}, interpolated), interpolated);
  bool has_normals = l.normals[i] == SurfaceLanes::vertex_normals, interpolated_in_range;
  vec3 n = normalize_in_range(interpolated, interpolated_in_range);
  bool usable = has_normals & usable_vertex_normal(n);
  vec3 shading_normal = usable ? on_side_of(n, hit.geometric_normal) : hit.geometric_normal;
  bool given = l.normals[i] == SurfaceLanes::given_normal;
  shading_normal = lane::select_bits(given, vec3{l.n0x[i], l.n0y[i], l.n0z[i]}, shading_normal);
  hit.wo = -normalize_in_range(direction, direction_in_range);
  hit.normal = front_face ? shading_normal : -shading_normal;
  hit.in_range = normal_in_range & direction_in_range & (interpolated_in_range | !has_normals);
  return hit;
}

// What every lane stores of its hit for the outputs and the later loops.
[[gnu::always_inline]] inline void store_hit(SurfaceLanes& l, int i, const LaneHit& hit, vec3 lobe_normal, bool valid) {
  l.fallback[i] = !hit.in_range;
  l.px[i] = hit.point.x, l.py[i] = hit.point.y, l.pz[i] = hit.point.z;
  l.nx[i] = hit.normal.x, l.ny[i] = hit.normal.y, l.nz[i] = hit.normal.z;
  l.gnx[i] = hit.geometric_normal.x, l.gny[i] = hit.geometric_normal.y, l.gnz[i] = hit.geometric_normal.z;
  l.error[i] = hit.error;
  l.lobe_nx[i] = lobe_normal.x, l.lobe_ny[i] = lobe_normal.y, l.lobe_nz[i] = lobe_normal.z;
  l.valid[i] = valid;
}
[[gnu::always_inline]] inline void store_bounce(SurfaceLanes& l, int i, bool scatters, vec3 origin, vec3 wi,
                                                float pdf, color3 weight, bool delta = false) {
  l.scatters[i] = scatters;
  l.delta[i] = delta;
  l.ox[i] = origin.x, l.oy[i] = origin.y, l.oz[i] = origin.z;
  l.wix[i] = wi.x, l.wiy[i] = wi.y, l.wiz[i] = wi.z;
  l.pdf[i] = pdf;
  l.weight_r[i] = weight.x, l.weight_g[i] = weight.y, l.weight_b[i] = weight.z;
}

// A Lambert lane: its hit, the lobes (lambert_bsdf.cpp) and their bounce (sample_warped), then
// sample_one_light for a point light with opaque shadows, and the two rays' origins (spawn_ray,
// spawn_ray_to).
template <int Hits>
[[gnu::always_inline]] inline void lambert_lane(SurfaceLanes& l, int i) {
  LaneHit hit = decode_lane<Hits>(l, i);
  color3 albedo = {l.albedo_r[i], l.albedo_g[i], l.albedo_b[i]};
  float cos_o = dot(hit.normal, hit.wo);
  vec3 lobe_normal = cos_o < 0 ? -hit.normal : hit.normal;
  bool valid = (std::abs(cos_o) > lambert_min_cosine) & lane::finite(cos_o);  // a lane's albedo is never black
  store_hit(l, i, hit, lobe_normal, valid);

  vec3 local = {l.cosine_x[i], l.cosine_y[i], l.cosine_z[i]};
  bool scatters = valid & (local.z >= lambert_min_cosine);
  vec3 wi = to_world(make_shading_frame(lobe_normal), local);
  store_bounce(l, i, scatters, offset_ray_origin(hit.point, {hit.error, hit.error, hit.error}, hit.geometric_normal, wi),
               wi, local.z * inv_pi, albedo);
  LaneLight light = point_light_lane(l, i, hit.point, LambertValue{lobe_normal, albedo, valid});
  store_light_outputs(l, i, light_outputs(l, i, light, hit.point, {hit.error, hit.error, hit.error}, hit.geometric_normal));
}

// A glossy lane's first loops. The first records the local cosines of wo and of the point
// light's direction, for glossy_albedos.
template <int Hits>
[[gnu::always_inline]] inline void record_glossy_lane(SurfaceLanes& l, int i) {
  LaneHit hit = decode_lane<Hits>(l, i);
  vec3 normal;
  l.energy_cos_o[i] = glossy_lane_frame(hit.normal, hit.wo, normal).z;
  point_light_lane(l, i, hit.point, GlossyRecord{normal, &l.energy_cos_i[i]});
}

// The albedo tables' values along the recorded cosines: along wo where `along_wo`, and along
// the light's direction where `which` (every lane when null). One lane at a time: the tables'
// reads are not loads a vector loop can make.
void glossy_albedos(SurfaceLanes& l, bool along_wo, const int32_t* which) {
  for (int i = 0; i < l.count; ++i) {
    MicrofacetEnergy e = glossy_material(l, i).energy;
    if (along_wo) {
      MicrofacetAlbedos at_o = microfacet_albedos(e, l.energy_cos_o[i]);
      l.albedo_o[i] = at_o.albedo, l.rise_o[i] = at_o.rise;
    }
    if (which && !which[i]) continue;
    MicrofacetAlbedos at_i = microfacet_albedos(e, l.energy_cos_i[i]);
    l.albedo_i[i] = at_i.albedo, l.rise_i[i] = at_i.rise;
  }
}
void glossy_light_albedos(SurfaceLanes& l, const int32_t* which) { glossy_albedos(l, false, which); }

// The loop proper: its hit, the metallic-roughness lobes and the point light's sample.
template <int Hits>
[[gnu::always_inline]] inline void glossy_lane(SurfaceLanes& l, int i) {
  LaneHit hit = decode_lane<Hits>(l, i);
  GlossyLaneMaterial m = glossy_material(l, i);
  GlossyLaneLobes lobes = make_glossy_lane_lobes(m, hit.normal, hit.wo, {l.albedo_o[i], l.rise_o[i]});
  store_hit(l, i, hit, lobes.normal, lobes.valid);
  l.wo_x[i] = lobes.wo.x, l.wo_y[i] = lobes.wo.y, l.wo_z[i] = lobes.wo.z;
  l.p_specular[i] = lobes.p_specular, l.p_diffuse[i] = lobes.p_diffuse;
  l.coating_o[i] = lobes.coating_o, l.loss_o[i] = lobes.loss_o, l.lambda_o[i] = lobes.lambda_o;
  LaneLight light = point_light_lane(l, i, hit.point, GlossyValue<false>{m, lobes, {l.albedo_i[i], l.rise_i[i]}});
  l.fallback[i] |= !light.in_range;
  store_light_outputs(l, i, light_outputs(l, i, light, hit.point, {hit.error, hit.error, hit.error}, hit.geometric_normal));
}

// The GGX lobe's directions where a glossy lane chose it (sample_specular): one lane at a time,
// in the one-path code's own function, whose sine and cosine no vector loop reproduces to the
// bit. Most lanes choose the diffuse lobe. Then the albedo tables' values along the bounce's
// direction, the chosen lobe's (glossy_albedos' reasons).
void sample_glossy_specular(SurfaceLanes& l) {
  for (int i = 0; i < l.count; ++i) {
    float cos_i = l.cosine_z[i];
    if (l.valid[i] && l.u_lobe[i] < l.p_specular[i]) {
      vec3 wo = {l.wo_x[i], l.wo_y[i], l.wo_z[i]};
      vec3 wi = reflect(wo, sample_ggx_visible_normal(wo, l.alpha[i], {l.u_x[i], l.u_y[i]}));
      l.specular_x[i] = wi.x, l.specular_y[i] = wi.y, l.specular_z[i] = wi.z;
      cos_i = wi.z;
    }
    MicrofacetAlbedos at_i = microfacet_albedos(glossy_material(l, i).energy, cos_i);
    l.albedo_i[i] = at_i.albedo, l.rise_i[i] = at_i.rise;
  }
}

// A glossy lane's bounce (sample_local, mixture_sample): the chosen lobe's direction weighted by
// the whole mixture, and the next ray's origin.
[[gnu::always_inline]] inline void glossy_bounce_lane(SurfaceLanes& l, int i) {
  GlossyLaneMaterial m = glossy_material(l, i);
  GlossyLaneLobes lobes = stored_glossy_lobes(l, i);
  bool specular = lobes.valid & (l.u_lobe[i] < lobes.p_specular);
  bool diffuse = lobes.valid & !specular & (l.u_lobe[i] < lobes.p_specular + lobes.p_diffuse);
  vec3 local = select(specular, {l.specular_x[i], l.specular_y[i], l.specular_z[i]},
                      {l.cosine_x[i], l.cosine_y[i], l.cosine_z[i]});
  float pdf;
  bool in_range;
  color3 f = eval_glossy_lane<true>(m, lobes, local, {l.albedo_i[i], l.rise_i[i]}, pdf, in_range);
  color3 weight = f / pdf;
  bool scatters = (specular & !(local.z <= 0)) | diffuse;
  scatters = scatters & (pdf > 0) & !lane::black(f) & lane::finite(weight) & !lane::black(weight);
  vec3 wi = to_world(make_shading_frame(lobes.normal), local);
  vec3 point = {l.px[i], l.py[i], l.pz[i]};
  float error = l.error[i];
  vec3 origin = offset_ray_origin(point, {error, error, error}, {l.gnx[i], l.gny[i], l.gnz[i]}, wi);
  l.fallback[i] |= (!in_range) & (specular | diffuse);
  store_bounce(l, i, scatters, origin, wi, pdf, weight);
}

// A Phong lane's first loop: its hit and lobes, and its point light's direction recorded for
// phong_powers (the light sample itself is taken by phong_light_and_bounce_lane).
template <int Hits>
[[gnu::always_inline]] inline void phong_lane(SurfaceLanes& l, int i) {
  LaneHit hit = decode_lane<Hits>(l, i);
  PhongLaneLobes lobes = make_phong_lane_lobes(hit.normal, hit.wo);
  store_hit(l, i, hit, lobes.normal, lobes.valid);
  l.wo_x[i] = lobes.wo.x, l.wo_y[i] = lobes.wo.y, l.wo_z[i] = lobes.wo.z;
  point_light_lane(l, i, hit.point, PhongRecord{lobes, &l.phong_cos[i]});
}

// The lobe a Phong lane's u_lobe chooses (sample_local: the same sums in the same order).
struct PhongLobeChoice {
  bool diffuse, glossy, mirror;
};
[[gnu::always_inline]] inline PhongLobeChoice choose_phong_lobe(const SurfaceLanes& l, int i, bool valid) {
  float u_lobe = l.u_lobe[i], threshold = l.p_diffuse[i];
  bool diffuse = valid & (u_lobe < threshold);
  bool glossy = valid & !diffuse & (u_lobe < (threshold += l.p_specular[i]));
  bool mirror = valid & !diffuse & !glossy & (u_lobe < threshold + l.p_mirror[i]);
  return {diffuse, glossy, mirror};
}

// A Phong lane's bounce direction (sample_local): the glossy lobe's where it is chosen, drawn
// one lane at a time in the library's function (std::pow, the sine and cosine), the mirror
// direction where the mirror is, otherwise the diffuse lobe's cosine-warped one; and the lobe
// power towards it.
void sample_phong_bounces(SurfaceLanes& l) {
  for (int i = 0; i < l.count; ++i) {
    PhongLaneLobes lobes = stored_phong_lobes(l, i);
    PhongLobeChoice lobe = choose_phong_lobe(l, i, lobes.valid);
    vec3 local = lobe.glossy   ? sample_phong_lobe(lobes.wo, l.exponent[i], {l.u_x[i], l.u_y[i]})
                 : lobe.mirror ? reflect_local(lobes.wo)
                               : vec3{l.cosine_x[i], l.cosine_y[i], l.cosine_z[i]};
    l.specular_x[i] = local.x, l.specular_y[i] = local.y, l.specular_z[i] = local.z;
    l.bounce_power[i] = lobes.valid ? phong_lobe_power(phong_cosine(lobes, local), l.exponent[i]) : 0.0f;
  }
}

// A Phong lane's point light sample (sample_one_light) and bounce (mixture_sample, or the
// mirror's delta_sample: kr over its probability), their lobe powers worked out.
[[gnu::always_inline]] inline void phong_light_and_bounce_lane(SurfaceLanes& l, int i) {
  PhongLaneLobes lobes = stored_phong_lobes(l, i);
  vec3 point = {l.px[i], l.py[i], l.pz[i]}, geometric = {l.gnx[i], l.gny[i], l.gnz[i]};
  float error = l.error[i];
  LaneLight light = point_light_lane(l, i, point, PhongValue{l, i, lobes, l.phong_power[i]});
  store_light_outputs(l, i, light_outputs(l, i, light, point, {error, error, error}, geometric));
  PhongLobeChoice lobe = choose_phong_lobe(l, i, lobes.valid);
  vec3 local = {l.specular_x[i], l.specular_y[i], l.specular_z[i]};
  float pdf;
  color3 f = eval_phong_lane(l, i, lobes, local, l.bounce_power[i], pdf);
  color3 weight = f / pdf;
  bool scatters =
      (lobe.diffuse | lobe.glossy) & (pdf > 0) & !lane::black(f) & lane::finite(weight) & !lane::black(weight);
  float p_mirror = l.p_mirror[i];
  color3 mirror_weight = color3{l.mirror_r[i], l.mirror_g[i], l.mirror_b[i]} / p_mirror;
  // The lobes are exclusive, so `scatters` is false where the mirror is chosen (as a select,
  // the loop was not vectorised).
  scatters = (lobe.mirror & !lane::black(mirror_weight)) | scatters;
  weight = select(lobe.mirror, mirror_weight, weight);
  pdf = lobe.mirror ? p_mirror : pdf;
  vec3 wi = to_world(make_shading_frame(lobes.normal), local);
  store_bounce(l, i, scatters, offset_ray_origin(point, {error, error, error}, geometric, wi), wi, pdf, weight, lobe.mirror);
}

// A lane whose light is an emitting triangle, after the first loop: its light sample replaces
// the point light's. A loop of its own: in one loop with the rest, GCC would not vectorise it.
template <RenderContext::LaneModel Model>
[[gnu::always_inline]] inline void triangle_lane(SurfaceLanes& l, int i) {
  vec3 point = {l.px[i], l.py[i], l.pz[i]};
  LaneLight light = triangle_light_lane(l, i, point, lane_bsdf<Model, true>(l, i));
  float largest = l.error[i];
  LightOutputs o = light_outputs(l, i, light, point, {largest, largest, largest}, {l.gnx[i], l.gny[i], l.gnz[i]});
  bool area = l.area[i] != 0;
  store_light_outputs_where(l, i, area, o);
  if constexpr (Model == RenderContext::LaneModel::glossy) l.fallback[i] |= (!light.in_range) & area;
}

// The direction, pdf, distance and radiance of the lights the lanes draw one lane at a time
// (sample_one_light): the environment (a search of the map's distribution, the sphere's
// trigonometry, the map's texels) and emitting spheres (sample_area_light's cone), in the
// library's own functions.
void draw_lane_lights(SurfaceLanes& l) {
  for (int i = 0; i < l.count; ++i) {
    if (!l.drawn[i]) continue;
    vec3 point = {l.px[i], l.py[i], l.pz[i]};
    vec2 u = {l.u_point_x[i], l.u_point_y[i]};
    if (const AreaLight* sphere = l.sphere[i]) {
      AreaLightSample s;
      bool ok = sample_area_light(*sphere, point, u, s) && area_light_emits(*sphere, s.normal, -s.direction);
      l.drawn_ok[i] = ok;
      s.direction = ok ? s.direction : vec3{0, 0, 1}, s.pdf = ok ? s.pdf : 1, s.distance = ok ? s.distance : 1;
      l.drawn_x[i] = s.direction.x, l.drawn_y[i] = s.direction.y, l.drawn_z[i] = s.direction.z;
      l.drawn_pdf[i] = s.pdf, l.drawn_distance[i] = s.distance * (1 - 1e-4f);
      continue;
    }
    vec3 wi;
    float pdf = sample_environment(*l.lights, {l.nx[i], l.ny[i], l.nz[i]}, l.u_environment[i], u, wi);
    color3 radiance = pdf > 0 ? eval_environment(*l.lights, wi) : color3{};
    l.drawn_ok[i] = pdf > 0;
    l.drawn_x[i] = wi.x, l.drawn_y[i] = wi.y, l.drawn_z[i] = wi.z, l.drawn_pdf[i] = pdf;
    l.drawn_distance[i] = std::numeric_limits<float>::infinity();
    l.drawn_r[i] = radiance.x, l.drawn_g[i] = radiance.y, l.drawn_b[i] = radiance.z;
  }
  if (l.model == RenderContext::LaneModel::glossy) {
    for (int i = 0; i < l.count; ++i) {  // a glossy lane's albedo tables towards the light drawn
      if (!l.drawn[i]) continue;
      vec3 normal = {l.lobe_nx[i], l.lobe_ny[i], l.lobe_nz[i]};
      l.energy_cos_i[i] = to_local(make_shading_frame(normal), {l.drawn_x[i], l.drawn_y[i], l.drawn_z[i]}).z;
    }
    glossy_light_albedos(l, l.drawn);
  }
  if (l.model != RenderContext::LaneModel::phong) return;
  for (int i = 0; i < l.count; ++i) {  // a Phong lane's lobe power towards the light drawn
    if (!l.drawn[i]) continue;
    PhongLaneLobes lobes = stored_phong_lobes(l, i);
    vec3 wi = to_local(make_shading_frame(lobes.normal), {l.drawn_x[i], l.drawn_y[i], l.drawn_z[i]});
    l.phong_power[i] = phong_lobe_power(phong_cosine(lobes, wi), l.exponent[i]);
  }
}

// A lane whose light draw_lane_lights drew: the BSDF there and MIS against its sampling,
// replacing the first loop's sample.
template <RenderContext::LaneModel Model>
[[gnu::always_inline]] inline void drawn_light_lane(SurfaceLanes& l, int i) {
  vec3 point = {l.px[i], l.py[i], l.pz[i]};
  vec3 wi = {l.drawn_x[i], l.drawn_y[i], l.drawn_z[i]};
  LaneBsdfValue bsdf = lane_bsdf<Model, true>(l, i)(wi);
  float light_pdf = l.drawn_pdf[i];
  color3 emitted = {l.drawn_r[i], l.drawn_g[i], l.drawn_b[i]};
  float pdf = l.select_pdf[i] * light_pdf;
  float weight = power_heuristic(pdf, bsdf.pdf);
  LaneLight light;
  light.direction = wi;
  light.distance = l.drawn_distance[i];
  light.lit = (l.drawn_ok[i] != 0) & !lane::black(emitted) & bsdf.nonzero;
  light.contribution = bsdf.f_cos * emitted * color3{1, 1, 1} * (weight / pdf);
  light.in_range = bsdf.in_range;
  float largest = l.error[i];
  LightOutputs o =
      light_outputs<true>(l, i, light, point, {largest, largest, largest}, {l.gnx[i], l.gny[i], l.gnz[i]});
  bool drawn = l.drawn[i] != 0;
  store_light_outputs_where(l, i, drawn, o);
  if constexpr (Model == RenderContext::LaneModel::glossy) l.fallback[i] |= (!light.in_range) & drawn;
}

// A lane whose light is a shaped delta light (a spot, a range or a directional light), after
// the first loop, which took it for a plain point light: this sample replaces that one.
template <RenderContext::LaneModel Model>
[[gnu::always_inline]] inline void shaped_delta_lane(SurfaceLanes& l, int i) {
  vec3 point = {l.px[i], l.py[i], l.pz[i]};
  LaneLight light = shaped_delta_light_lane(l, i, point, lane_bsdf<Model, false>(l, i));
  float largest = l.error[i];
  LightOutputs o =
      light_outputs<true>(l, i, light, point, {largest, largest, largest}, {l.gnx[i], l.gny[i], l.gnz[i]});
  bool shaped = l.shaped[i] != 0;
  store_light_outputs_where(l, i, shaped, o);
  if constexpr (Model == RenderContext::LaneModel::glossy) l.fallback[i] |= (!light.in_range) & shaped;
}

// A classic spot's falloff at the lane's point (delta_light.cpp, spot_falloff): cos^exponent in
// front of the light, nothing behind it. The cosine is shaped_delta_light_lane's, in the same
// operations; std::pow, which no vector loop reproduces to the bit, one lane at a time.
void spot_powers(SurfaceLanes& l) {
  for (int i = 0; i < l.count; ++i) {
    if (!l.shaped[i] || !l.classic_spot[i]) continue;
    vec3 to_light = vec3{l.light_x[i], l.light_y[i], l.light_z[i]} - vec3{l.px[i], l.py[i], l.pz[i]};
    vec3 towards = to_light * (1 / length(to_light));
    float cos_angle = dot(vec3{l.spot_x[i], l.spot_y[i], l.spot_z[i]}, -towards);
    l.spot_power[i] = cos_angle > 0 ? std::pow(cos_angle, l.spot_exponent[i]) : 0.0f;
  }
}

// Phong lanes' light loops take two passes: the first records each light direction's cosine
// (PhongRecord), phong_powers raises it where `which` (every lane when null), and the loop
// proper reads the power (PhongValue).
[[gnu::always_inline]] inline void record_shaped_phong(SurfaceLanes& l, int i) {
  shaped_delta_light_lane(l, i, {l.px[i], l.py[i], l.pz[i]}, PhongRecord{stored_phong_lobes(l, i), &l.phong_cos[i]});
}
[[gnu::always_inline]] inline void record_triangle_phong(SurfaceLanes& l, int i) {
  triangle_light_lane(l, i, {l.px[i], l.py[i], l.pz[i]}, PhongRecord{stored_phong_lobes(l, i), &l.phong_cos[i]});
}
void phong_powers(SurfaceLanes& l, const int32_t* which) {
  for (int i = 0; i < l.count; ++i)
    if (!which || which[i]) l.phong_power[i] = phong_lobe_power(l.phong_cos[i], l.exponent[i]);
}
// Glossy lanes' light loops likewise: GlossyRecord, glossy_light_albedos, GlossyValue.
[[gnu::always_inline]] inline void record_shaped_glossy(SurfaceLanes& l, int i) {
  vec3 normal = {l.lobe_nx[i], l.lobe_ny[i], l.lobe_nz[i]};
  shaped_delta_light_lane(l, i, {l.px[i], l.py[i], l.pz[i]}, GlossyRecord{normal, &l.energy_cos_i[i]});
}
[[gnu::always_inline]] inline void record_triangle_glossy(SurfaceLanes& l, int i) {
  vec3 normal = {l.lobe_nx[i], l.lobe_ny[i], l.lobe_nz[i]};
  triangle_light_lane(l, i, {l.px[i], l.py[i], l.pz[i]}, GlossyRecord{normal, &l.energy_cos_i[i]});
}

// The kernel's loops, compiled once per instruction set. Each is a loop of its own: GCC
// vectorises these one at a time, not together.
template <RenderContext::LaneModel Model, bool AnyArea, int Hits>
[[gnu::always_inline]] inline void shade_lanes(SurfaceLanes& l) {
  using LaneModel = RenderContext::LaneModel;
  constexpr bool phong = Model == LaneModel::phong, glossy = Model == LaneModel::glossy;
  if constexpr (glossy) {
    for (int i = 0; i < l.count; ++i) record_glossy_lane<Hits>(l, i);
    glossy_albedos(l, true, nullptr);
    for (int i = 0; i < l.count; ++i) glossy_lane<Hits>(l, i);
    sample_glossy_specular(l);
    for (int i = 0; i < l.count; ++i) glossy_bounce_lane(l, i);
  } else if constexpr (phong) {
    for (int i = 0; i < l.count; ++i) phong_lane<Hits>(l, i);
    phong_powers(l, nullptr);
    sample_phong_bounces(l);
    for (int i = 0; i < l.count; ++i) phong_light_and_bounce_lane(l, i);
  } else {
    for (int i = 0; i < l.count; ++i) lambert_lane<Hits>(l, i);
  }
  if (l.any_shaped) {
    if (l.any_classic_spot) spot_powers(l);
    if constexpr (phong) {
      for (int i = 0; i < l.count; ++i) record_shaped_phong(l, i);
      phong_powers(l, l.shaped);
    } else if constexpr (glossy) {
      for (int i = 0; i < l.count; ++i) record_shaped_glossy(l, i);
      glossy_light_albedos(l, l.shaped);
    }
    for (int i = 0; i < l.count; ++i) shaped_delta_lane<Model>(l, i);
  }
  if (l.any_drawn) {
    draw_lane_lights(l);
    for (int i = 0; i < l.count; ++i) drawn_light_lane<Model>(l, i);
  }
  if constexpr (AnyArea) {
    if constexpr (phong) {
      for (int i = 0; i < l.count; ++i) record_triangle_phong(l, i);
      phong_powers(l, l.area);
    } else if constexpr (glossy) {
      for (int i = 0; i < l.count; ++i) record_triangle_glossy(l, i);
      glossy_light_albedos(l, l.area);
    }
    for (int i = 0; i < l.count; ++i) triangle_lane<Model>(l, i);
  }
}
template <RenderContext::LaneModel Model, bool AnyArea, int Hits>
[[gnu::target("avx2")]] void shade_lanes_avx2(SurfaceLanes& l) {
  shade_lanes<Model, AnyArea, Hits>(l);
}
template <RenderContext::LaneModel Model, bool AnyArea, int Hits>
void shade_lanes_baseline(SurfaceLanes& l) {
  shade_lanes<Model, AnyArea, Hits>(l);
}
template <RenderContext::LaneModel Model, bool AnyArea, int Hits>
void shade_lanes_on(SurfaceLanes& l, bool avx2) {
  avx2 ? shade_lanes_avx2<Model, AnyArea, Hits>(l) : shade_lanes_baseline<Model, AnyArea, Hits>(l);
}
template <RenderContext::LaneModel Model, bool AnyArea>
void shade_lanes_on(SurfaceLanes& l, bool avx2) {
  constexpr int transformed = SurfaceLanes::transformed_hits, shapes = SurfaceLanes::shape_hits;
  switch (l.hit_kinds) {
    case 0: return shade_lanes_on<Model, AnyArea, 0>(l, avx2);
    case transformed: return shade_lanes_on<Model, AnyArea, transformed>(l, avx2);
    case shapes: return shade_lanes_on<Model, AnyArea, shapes>(l, avx2);
    default: return shade_lanes_on<Model, AnyArea, transformed | shapes>(l, avx2);
  }
}
template <RenderContext::LaneModel Model>
void shade_lanes_on(SurfaceLanes& l, bool avx2) {
  l.any_area ? shade_lanes_on<Model, true>(l, avx2) : shade_lanes_on<Model, false>(l, avx2);
}

}  // namespace

void shade_surface_lanes(SurfaceLanes& lanes, LaneIsa isa) {
  bool avx2 = resolve_lane_isa(isa) == LaneIsa::avx2;
  using LaneModel = RenderContext::LaneModel;
  switch (lanes.model) {
    case LaneModel::glossy: return shade_lanes_on<LaneModel::glossy>(lanes, avx2);
    case LaneModel::phong: return shade_lanes_on<LaneModel::phong>(lanes, avx2);
    default: return shade_lanes_on<LaneModel::lambert>(lanes, avx2);
  }
}

void set_lane_shaped_light(SurfaceLanes& l, int i, const LightDesc& light) {
  bool spot = light.kind == LightKind::spot, directional = light.kind == LightKind::directional;
  bool classic = spot && !light.use_cone;
  l.any_shaped = true;
  l.any_classic_spot |= classic;
  l.spot[i] = spot && light.use_cone, l.classic_spot[i] = classic, l.directional[i] = directional;
  l.spot_exponent[i] = light.spot_exponent;
  l.range[i] = directional ? 0.0f : light.range;  // a directional light has no range
  l.spot_x[i] = light.direction.x, l.spot_y[i] = light.direction.y, l.spot_z[i] = light.direction.z;
  // A glTF spot's cone, worked out as spot_falloff does; finite values for the other lights,
  // whose lanes compute a cone they do not use.
  if (l.spot[i]) {
    float cos_outer = std::cos(light.outer_cone), cos_inner = std::cos(light.inner_cone);
    l.cos_outer[i] = cos_outer;
    l.cone_scale[i] = 1.0f / std::max(0.001f, cos_inner - cos_outer);
  } else {
    l.cos_outer[i] = 0, l.cone_scale[i] = 1;
  }
}

RenderContext::LaneModel lane_model_of(const SurfaceMaterial& m, const BsdfMaterial& bsdf) {
  using LaneModel = RenderContext::LaneModel;
  bool plain = is_black(m.emission) && !m.unlit && m.opacity >= 1 && is_black(m.kt) && !(m.transmission > 0);
  if (plain && bsdf.lambert() && max_component(bsdf.lambert()->albedo) > 0) return LaneModel::lambert;
  if (plain && bsdf.metallic_roughness() && is_metallic_roughness_lane_case(*bsdf.metallic_roughness()))
    return LaneModel::glossy;
  // Phong with a glossy or mirror lobe beside a non-delta one (a Phong material with neither
  // is a Lambert; one with only a mirror takes no light sample) and no transmission.
  if (const PhongWeights* w = bsdf.phong(); plain && w && w->scatters && (w->p_glossy > 0 || w->p_mirror > 0) &&
                                            (w->p_diffuse > 0 || w->p_glossy > 0) && w->p_transmission == 0)
    return LaneModel::phong;
  return LaneModel::none;
}

}  // namespace radiant
