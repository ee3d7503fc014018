// The batch's vertices shaded in SIMD lanes: the gather of the vertices the surface lanes
// can shade (surface_lanes.h), and the scatter of their results back into the paths.
#pragma once

#include "integrators/path_variant.h"

namespace radiant {

// Internal to the path integrator: included by path.cpp alone.
namespace {

// Gathers the stage's vertices that the surface lanes can shade (surface_lanes.h) and shades
// them: a live path at a hit of a mesh's triangle, a sphere or a plane, whose material is a lane material,
// which chooses a point, spot or directional light, an emitting triangle or sphere, or
// the environment. Its light is chosen, a triangle's point drawn and a glossy material's lobe
// choice drawn here, as the one-path code would.
// `PhongLanes` (ctx.phong_lanes): compiled without the Phong lanes, the gather of a scene that
// has none costs what it did before they existed (about 1% of the Lambert box's instructions).
template <uint32_t E, bool LightSampling>
template <bool PhongLanes>
[[gnu::noinline]] void PathVariant<E, LightSampling>::shade_in_surface_lanes(const RenderContext& ctx, BatchWorkspace& w, int live_count) {
  using LaneModel = RenderContext::LaneModel;
  const SceneDesc& scene = *ctx.scene;
  const SceneAccel& accel = *ctx.accel;
  const LightTable& lights = *ctx.lights;
  constexpr int sets = PhongLanes ? 3 : 2;
  for (int set = 0; set < sets; ++set) {
    SurfaceLanes& l = w.surface[set];
    l.count = 0, l.any_area = l.any_shaped = l.any_classic_spot = l.any_drawn = false, l.hit_kinds = 0;
    l.model = LaneModel(set + 1);
  }
  for (int k = 0; k < live_count; ++k) {
    w.lane_of[k] = -1;
    const PathState& path = w.paths[w.live[k]];
    const HitId& id = w.hits[k];
    VertexDraws& drawn = w.drawn[k];
    int depth = path.depth;
    // With sub-paths (ctx.split > 1) a camera sample's first vertex is shaded once for all of
    // them (SharedFirstVertex), one path at a time.
    if (!id.valid() || depth >= path.max_depth || (depth == 0 && (path.first_hit || ctx.split > 1)) ||
        !drawn.has(bsdf_direction))
      continue;
    // Inside an absorbing volume the segment's absorption comes first (advance).
    if (enabled<E>(ctx.effects, effect_absorption) && path.medium >= 0) continue;
    // A mesh's triangle, a sphere or a plane.
    if (id.stroke >= 0) continue;  // lines and points take the single path
    const MeshDesc* mesh = id.instance >= 0 ? &scene.meshes[scene.instances[id.instance].mesh] : nullptr;
    if (mesh && moves_during_shutter(accel, id)) continue;  // placed at its ray's time: the single path
    const ShapeDesc* shape = mesh ? nullptr : &scene.shapes[id.shape];
    if (shape && shape->kind != ShapeKind::sphere && shape->kind != ShapeKind::plane) continue;
    int material_index = mesh ? mesh->material : shape->material;
    LaneModel model = ctx.lane_models[size_t(material_index)];
    if (model == LaneModel::none) continue;
    const SampleContext& sample = depth == 0 ? *path.sample : path.own;
    // The light: chosen by the light BVH ahead (choose_lights_ahead), or by power here.
    uint32_t slot = 0;
    float select_pdf;
    if (lights.sampler == LightSampler::bvh) {
      if (!drawn.light_chosen || !drawn.light_found) continue;
      slot = drawn.light_slot, select_pdf = drawn.light_probability;
    } else {
      if (lights.selection.empty()) continue;
      if (light_choice_draws(lights))
        slot = uint32_t(sample_discrete(lights.selection, drawn.has(light_choice)
                                                              ? drawn.light_choice
                                                              : sample_1d(sample, dimension(depth, light_choice))));
      select_pdf = lights.selection.pmf[slot];
    }
    // A point, spot or directional light, an emitting triangle or sphere, or the environment.
    const LightDesc* point = nullptr;
    const AreaLight* area = nullptr;
    if (slot < lights.delta_lights.size()) {
      point = &scene.lights[lights.delta_lights[slot]];
      if (point->kind == LightKind::ambient || !enabled<E>(ctx.effects, effect_direct_delta)) continue;
    } else if (slot < lights.environment_slot()) {
      area = &lights.area_lights[slot - lights.delta_lights.size()];
      if (!enabled<E>(ctx.effects, effect_emission)) continue;
    } else if (slot != lights.environment_slot() || !lights.has_environment() ||
               !enabled<E>(ctx.effects, effect_environment)) {
      continue;
    }
    // The material as the hit resolves it, and where a map bends the normal, that normal.
    const BsdfMaterial* bsdf_material = &ctx.flat_bsdf_materials[size_t(material_index)];
    std::optional<vec3> mapped_normal;
    if constexpr ((E & effect_group_textures) != 0) {
      if (enabled<E>(ctx.effects, effect_textures) || enabled<E>(ctx.effects, effect_normal_maps)) {
        model = resolve_lane_vertex(ctx, path, id, sample, w.scratch, w.resolved_bsdf, mapped_normal);
        if (model == LaneModel::none) continue;
        bsdf_material = &*w.resolved_bsdf;
      }
    }
    if constexpr (!PhongLanes)
      if (model == LaneModel::phong) continue;  // never: ctx.phong_lanes is set where one can be
    int set = PhongLanes ? int(model) - 1 : model == LaneModel::glossy;
    SurfaceLanes& l = PhongLanes ? w.surface[set] : model == LaneModel::glossy ? w.surface[1] : w.surface[0];
    int i = l.count++;
    w.lane_of[k] = PhongLanes ? set * max_batch_paths + i : model == LaneModel::glossy ? max_batch_paths + i : i;
    l.ngx[i] = id.geometric_normal_raw.x, l.ngy[i] = id.geometric_normal_raw.y, l.ngz[i] = id.geometric_normal_raw.z;
    if (mesh)
      set_triangle_hit(l, i, *mesh, accel, id);
    else
      set_shape_hit(l, i, *shape, path.ray, id);
    if (mapped_normal) {
      l.normals[i] = SurfaceLanes::given_normal;
      l.n0x[i] = mapped_normal->x, l.n0y[i] = mapped_normal->y, l.n0z[i] = mapped_normal->z;
    }
    l.dx[i] = path.ray.direction.x, l.dy[i] = path.ray.direction.y, l.dz[i] = path.ray.direction.z;
    const BsdfMaterial& material = *bsdf_material;
    if (model == LaneModel::lambert) {
      color3 albedo = material.lambert()->albedo;
      l.albedo_r[i] = albedo.x, l.albedo_g[i] = albedo.y, l.albedo_b[i] = albedo.z;
    } else if (model == LaneModel::glossy) {
      set_lane_glossy_material(l, i, *material.metallic_roughness());
      l.u_lobe[i] = glossy_lobe_choice(*material.metallic_roughness(), path, drawn);
      l.u_x[i] = drawn.direction.x, l.u_y[i] = drawn.direction.y;
    } else {
      set_phong_lane(l, i, *material.phong(), path, drawn);
    }
    bool triangle = area && area->shape == AreaLightShape::triangle;
    l.area[i] = triangle;
    l.drawn[i] = !point && !triangle;
    if (point) {
      set_lane_delta_light(l, i, *point);
    } else if (!triangle) {
      // The environment or a sphere: drawn one lane at a time by the kernel.
      l.any_drawn = true;
      l.sphere[i] = area;
      if (area) {
        color3 emission = area_light_emission<E>(ctx, *area, {});  // a sphere's is not textured
        l.drawn_r[i] = emission.x, l.drawn_g[i] = emission.y, l.drawn_b[i] = emission.z;
      } else {
        l.lights = &lights;
        l.u_environment[i] = sample_1d(sample, dimension(depth, environment_choice));
      }
      vec2 u = drawn.has(light_point) ? drawn.light_point : sample_2d(sample, dimension(depth, light_point));
      l.u_point_x[i] = u.x, l.u_point_y[i] = u.y;
      // A point light's fields the kernel also reads (its results are discarded): finite values.
      l.light_x[i] = l.light_y[i] = l.light_z[i] = 0;
      l.intensity_r[i] = l.intensity_g[i] = l.intensity_b[i] = 0;
      l.kc[i] = 1, l.kl[i] = l.kq[i] = 0;
      l.shaped[i] = 0;
    } else {
      l.any_area = true;
      l.light_x[i] = area->p0.x, l.light_y[i] = area->p0.y, l.light_z[i] = area->p0.z;
      l.light1_x[i] = area->p1.x, l.light1_y[i] = area->p1.y, l.light1_z[i] = area->p1.z;
      l.light2_x[i] = area->p2.x, l.light2_y[i] = area->p2.y, l.light2_z[i] = area->p2.z;
      l.light_nx[i] = area->normal.x, l.light_ny[i] = area->normal.y, l.light_nz[i] = area->normal.z;
      l.light_area[i] = area->area;
      l.two_sided[i] = area->two_sided;
      vec2 u = drawn.has(light_point) ? drawn.light_point : sample_2d(sample, dimension(depth, light_point));
      l.u_point_x[i] = u.x, l.u_point_y[i] = u.y;
      // The emission at the point the lane draws (sample_area_light's barycentrics depend on u
      // alone): an emission texture is read there, as sample_one_light reads it.
      color3 emission = area_light_emission<E>(ctx, *area, sample_uniform_triangle(u));
      l.intensity_r[i] = emission.x, l.intensity_g[i] = emission.y, l.intensity_b[i] = emission.z;
      // A point light's fields the kernel also reads (its results are discarded): finite values.
      l.kc[i] = 1, l.kl[i] = l.kq[i] = 0;
      l.shaped[i] = 0;
    }
    l.select_pdf[i] = select_pdf;
    l.cosine_x[i] = drawn.cosine.x, l.cosine_y[i] = drawn.cosine.y, l.cosine_z[i] = drawn.cosine.z;
    l.throughput_r[i] = path.throughput.x, l.throughput_g[i] = path.throughput.y, l.throughput_b[i] = path.throughput.z;
  }
  for (int set = 0; set < sets; ++set)
    if (w.surface[set].count > 0) shade_surface_lanes(w.surface[set]);
}

// A textured render's candidate for the lanes (shade_in_surface_lanes): its material resolved
// at the hit as advance() resolves it, into `bsdf`, and the lanes it can go to, if any. Where a
// normal or bump map bends the shading normal, `mapped_normal` is advance()'s (HitShading's
// authored normal), which the lanes then use instead of their own.
template <uint32_t E, bool LightSampling>
inline RenderContext::LaneModel PathVariant<E, LightSampling>::resolve_lane_vertex(const RenderContext& ctx, const PathState& path,
                                                    const HitId& id, const SampleContext& sample,
                                                    VertexScratch& scratch, std::optional<BsdfMaterial>& bsdf,
                                                    std::optional<vec3>& mapped_normal) {
  SurfaceHit hit = make_surface_hit(*ctx.accel, path.ray, id);
  const SurfaceMaterial& m = material_at<E>(ctx, id, hit, scratch.resolved, texture_footprint_scale(sample.index));
  RenderContext::LaneModel model = lane_model_of(m, bsdf.emplace(m));
  if (model != RenderContext::LaneModel::none && enabled<E>(ctx.effects, effect_normal_maps) &&
      (m.has_normal_map || m.has_bump_map))
    mapped_normal = make_hit_shading<E>(ctx.effects, hit, m, path.ray.direction).authored_normal;
  return model;
}

template <uint32_t E, bool LightSampling>
inline void PathVariant<E, LightSampling>::set_triangle_hit(SurfaceLanes& l, int i, const MeshDesc& mesh, const SceneAccel& accel, const HitId& id) {
  l.shape[i] = SurfaceLanes::triangle_hit;
  const uint32_t* tri = &mesh.indices[size_t(id.primitive) * 3];
  vec3 p0 = mesh.positions[tri[0]], p1 = mesh.positions[tri[1]], p2 = mesh.positions[tri[2]];
  l.p0x[i] = p0.x, l.p0y[i] = p0.y, l.p0z[i] = p0.z;
  l.p1x[i] = p1.x, l.p1y[i] = p1.y, l.p1z[i] = p1.z;
  l.p2x[i] = p2.x, l.p2y[i] = p2.y, l.p2z[i] = p2.z;
  l.b1[i] = id.barycentric.x, l.b2[i] = id.barycentric.y;
  l.normals[i] = mesh.normals.empty() ? SurfaceLanes::no_normals : SurfaceLanes::vertex_normals;
  l.transformed[i] = !accel.instance_identity[id.instance];
  if (l.transformed[i]) set_instance_transform(l, i, accel, id.instance);
  vec3 n0, n1, n2;  // zero without normals: the lane then ignores them
  if (!mesh.normals.empty()) n0 = mesh.normals[tri[0]], n1 = mesh.normals[tri[1]], n2 = mesh.normals[tri[2]];
  l.n0x[i] = n0.x, l.n0y[i] = n0.y, l.n0z[i] = n0.z;
  l.n1x[i] = n1.x, l.n1y[i] = n1.y, l.n1z[i] = n1.z;
  l.n2x[i] = n2.x, l.n2y[i] = n2.y, l.n2z[i] = n2.z;
}

// A sphere's or a plane's hit (fill_shape_hit): no vertex normals, no transform.
template <uint32_t E, bool LightSampling>
inline void PathVariant<E, LightSampling>::set_shape_hit(SurfaceLanes& l, int i, const ShapeDesc& shape, const Ray& ray, const HitId& id) {
  l.hit_kinds |= SurfaceLanes::shape_hits;
  l.shape[i] = shape.kind == ShapeKind::sphere ? SurfaceLanes::sphere_hit : SurfaceLanes::plane_hit;
  l.normals[i] = SurfaceLanes::no_normals, l.transformed[i] = 0;
  l.ray_ox[i] = ray.origin.x, l.ray_oy[i] = ray.origin.y, l.ray_oz[i] = ray.origin.z, l.ray_t[i] = id.t;
  l.center_x[i] = shape.center.x, l.center_y[i] = shape.center.y, l.center_z[i] = shape.center.z;
  l.radius[i] = shape.radius;
  l.axis_x[i] = shape.axis.x, l.axis_y[i] = shape.axis.y, l.axis_z[i] = shape.axis.z;
}

template <uint32_t E, bool LightSampling>
inline void PathVariant<E, LightSampling>::set_instance_transform(SurfaceLanes& l, int i, const SceneAccel& accel, int instance) {
  l.hit_kinds |= SurfaceLanes::transformed_hits;
  const mat4& to_world = accel.scene->instances[instance].transform;
  const mat4& to_object = accel.instance_inverse[instance];
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) l.to_world[r * 4 + c][i] = to_world.m[r][c];
    for (int c = 0; c < 3; ++c) l.to_object[r * 3 + c][i] = to_object.m[r][c];
  }
  l.orientation[i] = accel.instance_orientation[instance];
}

// The lobe choice a glossy vertex draws (scatter): only where its BSDF mixes lobes, which a
// lane material's does wherever its lobes are valid if it has both a specular and a diffuse
// lobe (elsewhere the vertex does not scatter, and the choice is not read).
template <uint32_t E, bool LightSampling>
inline float PathVariant<E, LightSampling>::glossy_lobe_choice(const MetallicRoughnessParams& p, const PathState& path, VertexDraws& drawn) {
  bool specular = p.metal > 0 || p.plastic * p.specular > 0;
  if (!(specular && has_cosine_lobes(p))) return 0.5f;
  drawn.lobe_choice_used = true;
  return drawn.has(lobe_choice) ? drawn.lobe_choice : sample_1d(path.own, dimension(path.depth, lobe_choice));
}

// A Phong lane's material, lobe choice and bounce numbers. Out of line: inlined, it made the
// gather dearer for every vertex, Lambert ones too (callgrind, .scene box: 0.24 M of its 14.4 M).
template <uint32_t E, bool LightSampling>
[[gnu::noinline]] void PathVariant<E, LightSampling>::set_phong_lane(SurfaceLanes& l, int i, const PhongWeights& w, const PathState& path,
                                             VertexDraws& drawn) {
  l.albedo_r[i] = w.kd.x, l.albedo_g[i] = w.kd.y, l.albedo_b[i] = w.kd.z;
  l.ks_r[i] = w.ks.x, l.ks_g[i] = w.ks.y, l.ks_b[i] = w.ks.z;
  l.exponent[i] = w.exponent, l.p_diffuse[i] = w.p_diffuse, l.p_specular[i] = w.p_glossy;
  l.mirror_r[i] = w.kr.x, l.mirror_g[i] = w.kr.y, l.mirror_b[i] = w.kr.z, l.p_mirror[i] = w.p_mirror;
  // The lobe choice scatter draws where the BSDF mixes lobes (Bsdf::chooses_lobe: more than
  // one of a lane material's diffuse, glossy and mirror lobes).
  float u_lobe = 0.5f;
  if (int(w.p_diffuse > 0) + int(w.p_glossy > 0) + int(w.p_mirror > 0) > 1) {
    drawn.lobe_choice_used = true;
    u_lobe = drawn.has(lobe_choice) ? drawn.lobe_choice : sample_1d(path.own, dimension(path.depth, lobe_choice));
  }
  l.u_lobe[i] = u_lobe;
  l.u_x[i] = drawn.direction.x, l.u_y[i] = drawn.direction.y;
}

// The rest of advance() for a vertex shaded in lane `i`: the light sample's result, the path's
// state and its next ray, as advance() sets them.
template <uint32_t E, bool LightSampling>
[[gnu::always_inline]] inline bool PathVariant<E, LightSampling>::finish_surface_lane(const RenderContext& ctx, PathState& path,
                                                      const SurfaceLanes& l, int i, const HitId& id,
                                                      const VertexDraws& drawn, LightSampleResult& light,
                                                      RayCounts& counts) {
  color3& throughput = path.throughput;
  light.traces = l.lit[i];
  if (light.traces) {
    counts.shadow++;
    light.unblocked = clamp_contribution(ctx, {l.light_r[i], l.light_g[i], l.light_b[i]}, path.depth);
    light.blocked = throughput * color3{};
    light.shadow_ray.origin = {l.shadow_ox[i], l.shadow_oy[i], l.shadow_oz[i]};
    light.shadow_ray.direction = {l.shadow_dx[i], l.shadow_dy[i], l.shadow_dz[i]};
    light.shadow_ray.tmax = l.shadow_infinite[i] ? std::numeric_limits<float>::infinity() : 1 - 1e-4f;
    light.shadow_ray.time = path.ray.time;
    if (!shadows_are_opaque<E>(ctx)) {
      light.target = {l.shadow_tx[i], l.shadow_ty[i], l.shadow_tz[i]};
      light.footprint_scale = texture_footprint_scale((path.depth == 0 ? *path.sample : path.own).index);
    }
  } else {
    path.radiance += throughput * color3{};
  }
  if (!l.scatters[i]) return false;
  int depth = path.depth;
  bool delta = l.delta[i];  // a Phong mirror's, which is never transmissive in the lanes
  if (delta) {
    if (!enabled<E>(ctx.effects, effect_reflection)) return false;
    path.ray_kind = &RayCounts::reflection;
  } else {
    if (!enabled<E>(ctx.effects, effect_indirect)) path.max_depth = std::min(path.max_depth, depth + 1);
    path.ray_kind = &RayCounts::indirect;
  }
  color3 weight = {l.weight_r[i], l.weight_g[i], l.weight_b[i]};
  throughput *= depth == 0 ? weight * path.split_weight : weight;
  path.specular_bounce = delta;
  path.previous_pdf = l.pdf[i];
  path.previous_position = {l.px[i], l.py[i], l.pz[i]};
  path.previous_normal = {l.nx[i], l.ny[i], l.nz[i]};
  if (ctx.lights->sampler == LightSampler::bvh) path.previous_choice = light_choice_point(*ctx.accel, path.ray, id);
  path.ray.origin = {l.ox[i], l.oy[i], l.oz[i]};
  path.ray.direction = {l.wix[i], l.wiy[i], l.wiz[i]};
  path.ray.tmax = std::numeric_limits<float>::infinity();
  path.depth = ++depth;
  if (depth >= roulette_start_depth) {
    float survive = std::min(1.0f, max_component(throughput) * path.split);
    float u = drawn.has(roulette) ? drawn.roulette : sample_1d(path.own, dimension(depth, roulette));
    if (u >= survive) return false;
    throughput /= survive;
  }
  return true;
}

}  // namespace

}  // namespace radiant
