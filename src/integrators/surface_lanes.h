// A batch's commonest path vertices shaded across SIMD lanes: a hit of a mesh's triangle, a sphere
// or a plane, lit (through a shadow ray the caller traces) by one point, spot or directional light, one
// emitting triangle or sphere, or the environment, with a Lambert material, a metallic-roughness
// one in the case metallic_roughness_lane.h takes, or a Phong one with a glossy or mirror lobe
// (`model`).
// The batched path tracer (integrators/path.cpp) gathers such vertices of a stage into these
// lanes, one set per model, shades them together and scatters the results back; every other
// vertex, and every lane this kernel cannot finish (`fallback`), is shaded one path at a time.
// Each lane's results are what the one-path code gives, to the bit: the same operations in the
// same order (math/lane_isa.h).
#pragma once

#include <cstdint>

#include "integrators/render_context.h"
#include "materials/bsdf_models.h"
#include "math/lane_isa.h"

namespace radiant {

struct SurfaceLanes {
  static constexpr int capacity = max_batch_paths;
  // Each array is a cache line longer than the lanes need: at 1 KiB apart, one lane's eighty
  // fields would all fall into four of the L1 cache's 64 sets and evict each other (1.18x the
  // render's time once vertex normals added ten arrays).
  static constexpr int stride = capacity + 16;
  // Inputs: the triangle (its vertices, Embree's barycentrics and unnormalised normal, and its
  // vertex normals where `normals` says so), the ray's direction, the albedo, the chosen light
  // and the probability it was chosen with, the bounce's cosine-warped local direction and the
  // path's throughput. The light: a point light's position, attenuation and intensity; or,
  // where `area`, an emitting triangle's corners (light_* the first), front normal, area,
  // sidedness and emission (in intensity_*), and the point's random numbers.
  alignas(32) float p0x[stride], p0y[stride], p0z[stride];
  alignas(32) float p1x[stride], p1y[stride], p1z[stride];
  alignas(32) float p2x[stride], p2y[stride], p2z[stride];
  alignas(32) float b1[stride], b2[stride];
  alignas(32) float ngx[stride], ngy[stride], ngz[stride];
  // Where the shading normal comes from: the geometric normal, the vertex normals (n0-n2), or,
  // where a normal or bump map bent it, the one-path code's own (given_normal: the authored side's
  // normal in n0, which the lanes only turn to face the ray).
  static constexpr int32_t no_normals = 0, vertex_normals = 1, given_normal = 2;
  alignas(32) int32_t normals[stride];
  alignas(32) float n0x[stride], n0y[stride], n0z[stride];
  alignas(32) float n1x[stride], n1y[stride], n1z[stride];
  alignas(32) float n2x[stride], n2y[stride], n2z[stride];
  // Where `transformed`, the triangle's instance places it: its transform's first three rows
  // (row-major), its inverse's upper 3x3 (row-major; normals go by its transpose) and the sign
  // of its determinant.
  alignas(32) int32_t transformed[stride];
  alignas(32) float to_world[12][stride];
  alignas(32) float to_object[9][stride];
  alignas(32) float orientation[stride];
  // What a lane hit: a triangle, or the analytic shape refine_shape_point moves the hit onto.
  static constexpr int32_t triangle_hit = 0, sphere_hit = 1, plane_hit = 2;
  // Where `shape` is not a triangle: the ray's origin and hit distance, and the shape's centre
  // (a point on a plane), radius and axis (a plane's normal); its triangle fields are read, not used.
  alignas(32) int32_t shape[stride];
  alignas(32) float ray_ox[stride], ray_oy[stride], ray_oz[stride], ray_t[stride];
  alignas(32) float center_x[stride], center_y[stride], center_z[stride], radius[stride];
  alignas(32) float axis_x[stride], axis_y[stride], axis_z[stride];
  alignas(32) float dx[stride], dy[stride], dz[stride];
  alignas(32) float albedo_r[stride], albedo_g[stride], albedo_b[stride];  // or a glossy lane's base colour
  alignas(32) float light_x[stride], light_y[stride], light_z[stride];
  alignas(32) float kc[stride], kl[stride], kq[stride];
  alignas(32) float intensity_r[stride], intensity_g[stride], intensity_b[stride];
  alignas(32) int32_t area[stride];
  alignas(32) float light1_x[stride], light1_y[stride], light1_z[stride];
  alignas(32) float light2_x[stride], light2_y[stride], light2_z[stride];
  alignas(32) float light_nx[stride], light_ny[stride], light_nz[stride];
  alignas(32) float light_area[stride];
  alignas(32) int32_t two_sided[stride];
  alignas(32) float u_point_x[stride], u_point_y[stride];
  // Where `shaped`, the delta light is a glTF spot (`spot`: its axis in spot_*, the cosine of its
  // outer cone and the smooth step's scale), a classic spot (`classic_spot`: its axis in spot_*
  // and its exponent; between the kernel's loops, its falloff cos^exponent in spot_power,
  // std::pow one lane at a time), has a range (`range` > 0), or is `directional` (its direction
  // of travel in spot_*); the point light's fields then hold finite values.
  alignas(32) int32_t shaped[stride], spot[stride], classic_spot[stride], directional[stride];
  alignas(32) float spot_x[stride], spot_y[stride], spot_z[stride], cos_outer[stride], cone_scale[stride];
  alignas(32) float spot_exponent[stride], spot_power[stride];
  alignas(32) float range[stride];
  // Where `drawn`, the light is sampled one lane at a time, in the library's functions, whose
  // trigonometry no vector loop reproduces to the bit: the environment (of `lights`, the
  // render's table; its choice between map and cosine sampling in u_environment, with u_point)
  // where `sphere` is null, otherwise that emitting sphere (with u_point; its emission in
  // drawn_r..b). The kernel draws the direction, pdf, distance (infinite for the environment)
  // and radiance into drawn_*, and `drawn_ok` where sample_one_light would go on.
  alignas(32) int32_t drawn[stride];
  const AreaLight* sphere[stride];
  alignas(32) float u_environment[stride];
  alignas(32) float drawn_x[stride], drawn_y[stride], drawn_z[stride], drawn_pdf[stride], drawn_distance[stride];
  alignas(32) float drawn_r[stride], drawn_g[stride], drawn_b[stride];
  alignas(32) int32_t drawn_ok[stride];
  const LightTable* lights = nullptr;
  alignas(32) float select_pdf[stride];
  alignas(32) float cosine_x[stride], cosine_y[stride], cosine_z[stride];
  alignas(32) float throughput_r[stride], throughput_g[stride], throughput_b[stride];
  // A glossy lane's material (GlossyLaneMaterial without its base colour), its lobe choice and
  // the bounce's random numbers (the GGX lobe warps them itself).
  alignas(32) float alpha[stride], ior[stride], ior_f0[stride], metal[stride], plastic[stride];
  alignas(32) float specular[stride], specular_f0_r[stride], specular_f0_g[stride], specular_f0_b[stride];
  // Its energy compensation (MicrofacetEnergy).
  alignas(32) float albedo_roughness[stride], albedo_ior[stride];
  alignas(32) float multiple_r[stride], multiple_g[stride], multiple_b[stride], multiple_normalization[stride];
  alignas(32) float coating_reflect[stride], coating_rise[stride], coating_multiple[stride];
  alignas(32) float diffuse_normalization[stride];
  alignas(32) float u_lobe[stride], u_x[stride], u_y[stride];
  // Between the kernel's loops, the local cosines of wo and of a light's or the bounce's
  // direction, and the albedo tables' values there (microfacet_albedos, one lane at a time:
  // table reads keep a loop from vectorising).
  alignas(32) float energy_cos_o[stride], energy_cos_i[stride];
  alignas(32) float albedo_o[stride], rise_o[stride], albedo_i[stride], rise_i[stride];
  // A Phong lane's material (PhongWeights: kd in albedo_*, kr in mirror_*, its lobe
  // probabilities in p_diffuse, p_specular (glossy) and p_mirror) and, between the kernel's
  // loops, the cosine of the angle between a light's direction and wo's mirror direction, and
  // its power (phong_lobe_power: std::pow, one lane at a time), and the same power for the
  // bounce's direction.
  alignas(32) float ks_r[stride], ks_g[stride], ks_b[stride], exponent[stride];
  alignas(32) float mirror_r[stride], mirror_g[stride], mirror_b[stride], p_mirror[stride];
  alignas(32) float phong_cos[stride], phong_power[stride], bounce_power[stride];

  // Outputs. `fallback`: a value left float's normal range where the one-path code rescales it;
  // the vertex must be shaded one path at a time. Otherwise: the hit's position and the
  // shading normal facing the ray (the path's previous_*); `scatters`, and where it does the
  // next ray (origin, direction wi), its pdf, the throughput's weight and whether the bounce is
  // a delta lobe's (`delta`: a Phong lane's mirror); `lit`, and where it is the shadow ray
  // (origin, direction; tmax 1 - 1e-4, or infinite where `shadow_infinite`: the sun or the
  // environment), where it ends (shadow_target's; not set for an infinite one) and the light's
  // contribution through the throughput.
  alignas(32) int32_t fallback[stride], scatters[stride], delta[stride], lit[stride];
  alignas(32) float px[stride], py[stride], pz[stride];
  alignas(32) float nx[stride], ny[stride], nz[stride];
  alignas(32) float ox[stride], oy[stride], oz[stride];
  alignas(32) float wix[stride], wiy[stride], wiz[stride];
  alignas(32) float pdf[stride];
  alignas(32) float weight_r[stride], weight_g[stride], weight_b[stride];
  alignas(32) float shadow_ox[stride], shadow_oy[stride], shadow_oz[stride];
  alignas(32) float shadow_dx[stride], shadow_dy[stride], shadow_dz[stride];
  alignas(32) float shadow_tx[stride], shadow_ty[stride], shadow_tz[stride];
  alignas(32) int32_t shadow_infinite[stride];
  alignas(32) float light_r[stride], light_g[stride], light_b[stride];
  // Between the kernel's loops: each hit's geometric normal, error bound, lobe normal and
  // whether the lobes are valid; a glossy lane's local wo, lobe probabilities, what the coating
  // lets through, what single scattering loses and GGX Lambda along wo, and its GGX lobe's direction (local) where chosen;
  // a Phong lane's local wo and its bounce's local direction.
  alignas(32) float gnx[stride], gny[stride], gnz[stride], error[stride];
  alignas(32) float lobe_nx[stride], lobe_ny[stride], lobe_nz[stride];
  alignas(32) int32_t valid[stride];
  alignas(32) float wo_x[stride], wo_y[stride], wo_z[stride];
  alignas(32) float p_specular[stride], p_diffuse[stride], coating_o[stride], loss_o[stride];
  alignas(32) float lambda_o[stride];
  alignas(32) float specular_x[stride], specular_y[stride], specular_z[stride];
  int count = 0;
  RenderContext::LaneModel model = RenderContext::LaneModel::lambert;  // the lanes' model (not none)
  // Set by whoever fills the lanes: whether any lane's light is a triangle, a shaped delta
  // light (a classic spot among them), or drawn (the environment or a sphere), and which kinds
  // of hit beside untransformed triangles the lanes hold. The kernel leaves out what none needs.
  bool any_area = false, any_shaped = false, any_classic_spot = false, any_drawn = false;
  static constexpr int transformed_hits = 1, shape_hits = 2;
  int hit_kinds = 0;
};

// Shades lanes [0, count).
void shade_surface_lanes(SurfaceLanes& lanes, LaneIsa isa = LaneIsa::best);

// Lane i's glossy material: the metallic-roughness parameters a glossy lane reads.
inline void set_lane_glossy_material(SurfaceLanes& l, int i, const MetallicRoughnessParams& p) {
  l.albedo_r[i] = p.base.x, l.albedo_g[i] = p.base.y, l.albedo_b[i] = p.base.z;
  l.alpha[i] = p.alpha, l.ior[i] = p.ior, l.ior_f0[i] = p.ior_f0;
  l.metal[i] = p.metal, l.plastic[i] = p.plastic, l.specular[i] = p.specular;
  l.specular_f0_r[i] = p.specular_f0.x, l.specular_f0_g[i] = p.specular_f0.y, l.specular_f0_b[i] = p.specular_f0.z;
  const MicrofacetEnergy& e = p.energy;
  l.albedo_roughness[i] = e.roughness, l.albedo_ior[i] = e.ior;
  l.multiple_r[i] = e.multiple_scattering.x, l.multiple_g[i] = e.multiple_scattering.y;
  l.multiple_b[i] = e.multiple_scattering.z, l.multiple_normalization[i] = e.multiple_normalization;
  l.coating_reflect[i] = e.coating_reflect, l.coating_rise[i] = e.coating_rise, l.coating_multiple[i] = e.coating_multiple;
  l.diffuse_normalization[i] = e.diffuse_normalization;
}

// Lane i's fields for a shaped delta light (set_lane_delta_light), and sets any_shaped (and
// any_classic_spot for a classic spot).
void set_lane_shaped_light(SurfaceLanes& lanes, int i, const LightDesc& light);

// Lane i's light fields for a delta light: a point light, a glTF or classic spot, or a
// directional light. Inline: the plain point light is every lane's light on most boxes.
[[gnu::always_inline]] inline void set_lane_delta_light(SurfaceLanes& l, int i, const LightDesc& light) {
  l.light_x[i] = light.position.x, l.light_y[i] = light.position.y, l.light_z[i] = light.position.z;
  l.kc[i] = light.kc, l.kl[i] = light.kl, l.kq[i] = light.kq;
  l.intensity_r[i] = light.intensity.x, l.intensity_g[i] = light.intensity.y, l.intensity_b[i] = light.intensity.z;
  bool shaped = light.kind != LightKind::point || light.range > 0;
  l.shaped[i] = shaped;
  if (shaped) set_lane_shaped_light(l, i, light);
}

// Which lanes can shade a vertex whose material resolved to `m` (`bsdf` its BSDF material), if
// any: opaque, not emitting, lit; Lambertian with some albedo, the metallic-roughness case of
// materials/metallic_roughness_lane.h, or Phong with a glossy or mirror lobe beside a
// non-delta one, and no transmission. Normal and bump maps are the caller's (given_normal).
RenderContext::LaneModel lane_model_of(const SurfaceMaterial& m, const BsdfMaterial& bsdf);

}  // namespace radiant
