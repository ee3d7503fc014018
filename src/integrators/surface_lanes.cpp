#include "integrators/surface_lanes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "accel/ray.h"
#include "integrators/surface_lane_bsdfs.h"
#include "integrators/surface_lane_hit.h"
#include "integrators/surface_lane_lights.h"
#include "lights/area_light.h"
#include "lights/environment_light.h"
#include "materials/bsdf_models.h"
#include "materials/metallic_roughness_lane.h"
#include "materials/microfacet.h"
#include "materials/shading_frame.h"
#include "sampling/warp.h"

namespace radiant {

namespace {

using lane::largest_float;
using lane::normalize_in_range;
using lane::select;

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
    l.spot_power[i] = classic_spot_falloff(cos_angle, l.spot_exponent[i]);
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
    SpotCone cone = spot_cone(light);
    l.cos_outer[i] = cone.cos_outer, l.cone_scale[i] = cone.scale;
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
