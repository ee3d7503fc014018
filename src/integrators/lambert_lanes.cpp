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

// One lane: make_surface_hit (an untransformed triangle), make_hit_shading,
// the Lambert lobes and their bounce (sample_warped), then sample_one_light for a point light
// without range with opaque shadows, and the two rays' origins (spawn_ray, spawn_ray_to).
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
  constexpr float largest_float = std::numeric_limits<float>::max();
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

  // The point light's sample (delta_light.h) and its contribution (path.cpp, sample_one_light).
  vec3 to_light = vec3{l.light_x[i], l.light_y[i], l.light_z[i]} - point;
  float d = length(to_light);
  vec3 light_direction = to_light * (1 / d);
  float attenuation = l.kc[i] + l.kl[i] * d + l.kq[i] * d * d;
  color3 irradiance = color3{l.intensity_r[i], l.intensity_g[i], l.intensity_b[i]} * (1.0f / attenuation);
  float cos_i = dot(lobe_normal, light_direction);
  color3 f_cos = albedo * (inv_pi * cos_i);
  bool lit = (d > 0) & (attenuation > 0) & valid & (cos_i >= lambert_min_cosine) &
             ((f_cos.x != 0) | (f_cos.y != 0) | (f_cos.z != 0));
  color3 contribution = color3{l.throughput_r[i], l.throughput_g[i], l.throughput_b[i]} *
                        (f_cos * irradiance * color3{1, 1, 1} / l.select_pdf[i]);
  vec3 target = point + light_direction * d;
  vec3 shadow_origin = offset_lane(point, error, geometric_normal, target - point);
  vec3 next_origin = offset_lane(point, error, geometric_normal, wi);

  l.fallback[i] = !(normal_in_range & direction_in_range & (interpolated_in_range | !has_normals));
  l.scatters[i] = scatters;
  l.lit[i] = lit;
  l.px[i] = point.x, l.py[i] = point.y, l.pz[i] = point.z;
  l.nx[i] = normal.x, l.ny[i] = normal.y, l.nz[i] = normal.z;
  l.ox[i] = next_origin.x, l.oy[i] = next_origin.y, l.oz[i] = next_origin.z;
  l.wix[i] = wi.x, l.wiy[i] = wi.y, l.wiz[i] = wi.z;
  l.pdf[i] = local.z * inv_pi;
  l.shadow_ox[i] = shadow_origin.x, l.shadow_oy[i] = shadow_origin.y, l.shadow_oz[i] = shadow_origin.z;
  vec3 shadow_direction = target - shadow_origin;
  l.shadow_dx[i] = shadow_direction.x, l.shadow_dy[i] = shadow_direction.y, l.shadow_dz[i] = shadow_direction.z;
  l.light_r[i] = contribution.x, l.light_g[i] = contribution.y, l.light_b[i] = contribution.z;
}

[[gnu::target("avx2")]] void shade_lanes_avx2(LambertLanes& l) {
  for (int i = 0; i < l.count; ++i) shade_lane(l, i);
}
void shade_lanes_baseline(LambertLanes& l) {
  for (int i = 0; i < l.count; ++i) shade_lane(l, i);
}

}  // namespace

void shade_lambert_lanes(LambertLanes& lanes, LaneIsa isa) {
  if (resolve_lane_isa(isa) == LaneIsa::avx2)
    shade_lanes_avx2(lanes);
  else
    shade_lanes_baseline(lanes);
}

}  // namespace radiant
