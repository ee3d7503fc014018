#include "integrators/lambert_lanes.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "accel/ray.h"
#include "materials/bsdf_models.h"
#include "materials/shading_frame.h"

namespace radiant {

namespace {

constexpr float largest_float = std::numeric_limits<float>::max();

// A per-component select: a ternary on whole vectors is a branch GCC does not if-convert.
[[gnu::always_inline]] inline vec3 select(bool c, vec3 a, vec3 b) {
  return {c ? a.x : b.x, c ? a.y : b.y, c ? a.z : b.z};
}

// normalize() without its rescaling branch, which no vector loop can take: `in_range` says
// whether the result is normalize()'s (otherwise the lane falls back).
[[gnu::always_inline]] inline vec3 normalize_in_range(vec3 a, bool& in_range) {
  float l2 = dot(a, a);
  in_range = (l2 >= std::numeric_limits<float>::min()) & (l2 <= std::numeric_limits<float>::max());
  return a * (1 / std::sqrt(l2));
}

// next_float and offset_ray_origin (accel/ray.h) as selects without a branch, which a vector
// loop needs: the same values.
[[gnu::always_inline]] inline float step_lane(float coordinate, float normal) {
  uint32_t bits = std::bit_cast<uint32_t>(coordinate);
  bool up = normal > 0;
  uint32_t stepped = bits + (((coordinate > 0) == up) ? 1u : ~0u);
  stepped = coordinate == 0 ? (up ? 1u : 0x80000001u) : stepped;
  bool steps = (bits & 0x7f800000u) != 0x7f800000u && normal != 0;
  return std::bit_cast<float>(steps ? stepped : bits);
}
[[gnu::always_inline]] inline vec3 offset_lane(vec3 p, vec3 error, vec3 n, vec3 w) {
  vec3 away = dot(w, n) < 0 ? -n : n;
  vec3 po = p + away * std::max(dot(abs(n), error), 1e-20f);
  return {step_lane(po.x, away.x), step_lane(po.y, away.y), step_lane(po.z, away.z)};
}

// What a light sample leaves for its shadow ray: the direction to the light, how far the ray
// goes, the contribution before the throughput, and whether there is one.
struct LaneLight {
  vec3 direction;
  float distance;
  color3 contribution;
  bool lit;
};

// A point light without range (delta_light.h, sample_delta_light) and its contribution
// (path.cpp, sample_one_light).
[[gnu::always_inline]] inline LaneLight point_light_lane(const LambertLanes& l, int i, vec3 point, vec3 lobe_normal,
                                                          color3 albedo, bool valid) {
  LaneLight s;
  vec3 to_light = vec3{l.light_x[i], l.light_y[i], l.light_z[i]} - point;
  float d = length(to_light);
  s.direction = to_light * (1 / d);
  s.distance = d;
  float attenuation = l.kc[i] + l.kl[i] * d + l.kq[i] * d * d;
  color3 irradiance = color3{l.intensity_r[i], l.intensity_g[i], l.intensity_b[i]} * (1.0f / attenuation);
  float cos_i = dot(lobe_normal, s.direction);
  color3 f_cos = albedo * (inv_pi * cos_i);
  s.lit = (d > 0) & (attenuation > 0) & valid & (cos_i >= lambert_min_cosine) &
          ((f_cos.x != 0) | (f_cos.y != 0) | (f_cos.z != 0));
  s.contribution = f_cos * irradiance * color3{1, 1, 1} / l.select_pdf[i];
  return s;
}

// An emitting triangle (area_light.cpp, sample_area_light and area_light_emits; Heitz's
// mapping of sample_uniform_triangle) and its contribution with MIS against the Lambert bounce.
[[gnu::always_inline]] inline LaneLight triangle_light_lane(const LambertLanes& l, int i, vec3 point,
                                                             vec3 lobe_normal, color3 albedo, bool valid) {
  LaneLight s;
  float ux = l.u_point_x[i], uy = l.u_point_y[i];
  bool lower = ux < uy;
  float half_x = ux / 2, half_y = uy / 2;
  vec2 b = {lower ? half_x : ux - half_y, lower ? uy - half_x : half_y};
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
  float cos_i = dot(lobe_normal, s.direction);
  float bsdf_pdf = cos_i * inv_pi;
  color3 f_cos = albedo * (inv_pi * cos_i);
  float pdf = l.select_pdf[i] * light_pdf;
  float a = pdf * pdf, c = bsdf_pdf * bsdf_pdf;  // power_heuristic (sampling/warp.h)
  float weight = a + c > 0 ? a / (a + c) : 0.0f;
  s.distance = d * (1 - 1e-4f);
  s.lit = (d > 0) & (area > 0) & (cos_light > 1e-7f) & (std::abs(light_pdf) <= largest_float) &
          emits & ((emitted.x != 0) | (emitted.y != 0) | (emitted.z != 0)) & valid & (cos_i >= lambert_min_cosine) &
          ((f_cos.x != 0) | (f_cos.y != 0) | (f_cos.z != 0));
  s.contribution = f_cos * emitted * color3{1, 1, 1} * (weight / pdf);
  return s;
}

// A light sample's outputs: whether it lights the point, its contribution through the
// throughput, and its shadow ray (spawn_ray_to towards the light, as set_shadow_ray).
struct LightOutputs {
  int32_t lit;
  color3 contribution;
  vec3 shadow_origin, shadow_direction;
};
[[gnu::always_inline]] inline LightOutputs light_outputs(const LambertLanes& l, int i, const LaneLight& light,
                                                         vec3 point, vec3 error, vec3 geometric_normal) {
  LightOutputs o;
  o.lit = light.lit;
  o.contribution = color3{l.throughput_r[i], l.throughput_g[i], l.throughput_b[i]} * light.contribution;
  vec3 target = point + light.direction * light.distance;
  o.shadow_origin = offset_lane(point, error, geometric_normal, target - point);
  o.shadow_direction = target - o.shadow_origin;
  return o;
}
[[gnu::always_inline]] inline LightOutputs stored_light_outputs(const LambertLanes& l, int i) {
  return {l.lit[i], {l.light_r[i], l.light_g[i], l.light_b[i]}, {l.shadow_ox[i], l.shadow_oy[i], l.shadow_oz[i]},
          {l.shadow_dx[i], l.shadow_dy[i], l.shadow_dz[i]}};
}
[[gnu::always_inline]] inline void store_light_outputs(LambertLanes& l, int i, const LightOutputs& o) {
  l.lit[i] = o.lit;
  l.light_r[i] = o.contribution.x, l.light_g[i] = o.contribution.y, l.light_b[i] = o.contribution.z;
  l.shadow_ox[i] = o.shadow_origin.x, l.shadow_oy[i] = o.shadow_origin.y, l.shadow_oz[i] = o.shadow_origin.z;
  l.shadow_dx[i] = o.shadow_direction.x, l.shadow_dy[i] = o.shadow_direction.y, l.shadow_dz[i] = o.shadow_direction.z;
}

// One lane: make_surface_hit (an untransformed triangle), make_hit_shading,
// the Lambert lobes and their bounce (sample_warped), then sample_one_light for a point light
// with opaque shadows, and the two rays' origins (spawn_ray, spawn_ray_to). `AnyArea`: keep
// what triangle_lane needs.
template <bool AnyArea>
[[gnu::always_inline]] inline void shade_lane(LambertLanes& l, int i) {
  vec3 p0 = {l.p0x[i], l.p0y[i], l.p0z[i]}, p1 = {l.p1x[i], l.p1y[i], l.p1z[i]}, p2 = {l.p2x[i], l.p2y[i], l.p2z[i]};
  float b1 = l.b1[i], b2 = l.b2[i];
  vec3 direction = {l.dx[i], l.dy[i], l.dz[i]};
  color3 albedo = {l.albedo_r[i], l.albedo_g[i], l.albedo_b[i]};

  // The hit (surface_hit.cpp, fill_triangle_hit).
  vec3 e1 = p1 - p0, e2 = p2 - p0;
  vec3 point = p0 + (b1 * e1 + b2 * e2);
  vec3 object_error = rounding_gamma(5) * (abs(b1 * e1) + abs(b2 * e2)) + rounding_gamma(2) * abs(point);
  float largest = max_component(object_error);
  vec3 error = {largest, largest, largest};
  bool normal_in_range, direction_in_range;
  vec3 geometric_normal = normalize_in_range({l.ngx[i], l.ngy[i], l.ngz[i]}, normal_in_range);
  bool front_face = dot(direction, geometric_normal) < 0;
  // Interpolated vertex normals, on the geometric normal's side, where they are usable.
  float b0 = 1 - b1 - b2;
  vec3 interpolated = vec3{l.n0x[i], l.n0y[i], l.n0z[i]} * b0 + vec3{l.n1x[i], l.n1y[i], l.n1z[i]} * b1 +
                      vec3{l.n2x[i], l.n2y[i], l.n2z[i]} * b2;
  bool has_normals = l.has_normals[i] != 0, interpolated_in_range;
  vec3 n = normalize_in_range(interpolated, interpolated_in_range);
  bool usable = has_normals & (std::abs(n.x) <= largest_float) & (std::abs(n.y) <= largest_float) &
                (std::abs(n.z) <= largest_float) & (length_squared(n) > 0.5f);
  vec3 facing = dot(n, geometric_normal) < 0 ? -n : n;
  vec3 shading_normal = usable ? facing : geometric_normal;

  // Its shading (hit_shading.h) and the Lambert lobes (lambert_bsdf.cpp).
  vec3 wo = -normalize_in_range(direction, direction_in_range);
  vec3 normal = front_face ? shading_normal : -shading_normal;
  float cos_o = dot(normal, wo);
  vec3 lobe_normal = cos_o < 0 ? -normal : normal;
  // std::isfinite(cos_o), as a comparison.
  bool valid = (std::abs(cos_o) > lambert_min_cosine) & (std::abs(cos_o) <= largest_float);

  // The bounce from the cosine-warped direction.
  vec3 local = {l.cosine_x[i], l.cosine_y[i], l.cosine_z[i]};
  bool scatters = valid & (local.z >= lambert_min_cosine);
  vec3 wi = to_world(make_shading_frame(lobe_normal), local);
  vec3 next_origin = offset_lane(point, error, geometric_normal, wi);

  l.fallback[i] = !(normal_in_range & direction_in_range & (interpolated_in_range | !has_normals));
  l.scatters[i] = scatters;
  l.px[i] = point.x, l.py[i] = point.y, l.pz[i] = point.z;
  l.nx[i] = normal.x, l.ny[i] = normal.y, l.nz[i] = normal.z;
  l.ox[i] = next_origin.x, l.oy[i] = next_origin.y, l.oz[i] = next_origin.z;
  l.wix[i] = wi.x, l.wiy[i] = wi.y, l.wiz[i] = wi.z;
  l.pdf[i] = local.z * inv_pi;
  if constexpr (AnyArea) {
    l.gnx[i] = geometric_normal.x, l.gny[i] = geometric_normal.y, l.gnz[i] = geometric_normal.z;
    l.error[i] = largest;
    l.lobe_nx[i] = lobe_normal.x, l.lobe_ny[i] = lobe_normal.y, l.lobe_nz[i] = lobe_normal.z;
    l.valid[i] = valid;
  }
  store_light_outputs(
      l, i, light_outputs(l, i, point_light_lane(l, i, point, lobe_normal, albedo, valid), point, error, geometric_normal));
}

// A lane whose light is an emitting triangle, after shade_lane: its light sample replaces the
// point light's. A loop of its own: in one loop with the rest, GCC would not vectorise it.
[[gnu::always_inline]] inline void triangle_lane(LambertLanes& l, int i) {
  vec3 point = {l.px[i], l.py[i], l.pz[i]};
  vec3 lobe_normal = {l.lobe_nx[i], l.lobe_ny[i], l.lobe_nz[i]};
  color3 albedo = {l.albedo_r[i], l.albedo_g[i], l.albedo_b[i]};
  LaneLight light = triangle_light_lane(l, i, point, lobe_normal, albedo, l.valid[i] != 0);
  float largest = l.error[i];
  LightOutputs o = light_outputs(l, i, light, point, {largest, largest, largest}, {l.gnx[i], l.gny[i], l.gnz[i]});
  // Stored in every lane, the point lights' lanes keeping what they had: a conditional store
  // is a branch without AVX2's masked stores.
  LightOutputs kept = stored_light_outputs(l, i);
  bool area = l.area[i] != 0;
  o.lit = area ? o.lit : kept.lit;
  o.contribution = select(area, o.contribution, kept.contribution);
  o.shadow_origin = select(area, o.shadow_origin, kept.shadow_origin);
  o.shadow_direction = select(area, o.shadow_direction, kept.shadow_direction);
  store_light_outputs(l, i, o);
}

template <bool AnyArea>
[[gnu::target("avx2")]] void shade_lanes_avx2(LambertLanes& l) {
  for (int i = 0; i < l.count; ++i) shade_lane<AnyArea>(l, i);
  if constexpr (AnyArea)
    for (int i = 0; i < l.count; ++i) triangle_lane(l, i);
}
template <bool AnyArea>
void shade_lanes_baseline(LambertLanes& l) {
  for (int i = 0; i < l.count; ++i) shade_lane<AnyArea>(l, i);
  if constexpr (AnyArea)
    for (int i = 0; i < l.count; ++i) triangle_lane(l, i);
}

}  // namespace

void shade_lambert_lanes(LambertLanes& lanes, LaneIsa isa) {
  bool avx2 = resolve_lane_isa(isa) == LaneIsa::avx2;
  if (lanes.any_area)
    avx2 ? shade_lanes_avx2<true>(lanes) : shade_lanes_baseline<true>(lanes);
  else
    avx2 ? shade_lanes_avx2<false>(lanes) : shade_lanes_baseline<false>(lanes);
}

}  // namespace radiant
