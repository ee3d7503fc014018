// The BSDFs a surface lane evaluates towards a light: Lambert, the metallic-roughness case of
// materials/metallic_roughness_lane.h and Phong, read from the lanes' arrays.
#pragma once

#include "materials/bsdf_models.h"
#include "materials/metallic_roughness_lane.h"
#include "materials/shading_frame.h"
#include "math/lane.h"

namespace radiant {

// Internal to the surface lanes: included by surface_lanes.cpp alone, after surface_lanes.h
// (SurfaceLanes), whose unit these files are part of.
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

}  // namespace

}  // namespace radiant
