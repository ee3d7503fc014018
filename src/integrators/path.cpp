#include "integrators/path.h"

#include <tbb/enumerable_thread_specific.h>

#include "integrators/path_lanes.h"
#include "integrators/path_variant.h"
#include "integrators/path_vertex.h"

namespace radiant {

namespace {

// Every live path's random numbers for the vertex it is at, drawn together in SIMD, a group
// of lanes per dimension: those its scene can use (a light point only with area or
// environment lights, a light choice only with one to make, roulette once a path can reach
// its start depth). Every sampler: a `.scene` file's jittered sampler keeps its pixel
// positions in path mode, and its vertices draw hashes that run in lanes as well as Sobol's.
// At least one path is live.
template <uint32_t E, bool LightSampling>
[[gnu::always_inline]] inline void PathVariant<E, LightSampling>::draw_ahead(const RenderContext& ctx, BatchWorkspace& w, int live_count) {
  const LightTable& lights = *ctx.lights;
  const PathState* paths = w.paths;
  const int* live = w.live;
  uint32_t wants = 1u << bsdf_direction;
  if (LightSampling && (!lights.area_lights.empty() || lights.has_environment())) wants |= 1u << light_point;
  if (LightSampling && light_choice_draws(lights)) wants |= 1u << light_choice;
  if (w.lobe_choices) wants |= 1u << lobe_choice;
  for (int k = 0; k < live_count; ++k)
    if (paths[live[k]].depth + 1 >= roulette_start_depth) wants |= 1u << roulette;
  SampleLanes& lanes = w.lanes;
  lanes.count = 0;
  constexpr VertexDimension groups[] = {bsdf_direction, light_point, light_choice, lobe_choice, roulette};
  static_assert(SampleLanes::capacity >= std::size(groups) * max_batch_paths);
  for (VertexDimension d : groups) {
    if (!(wants & (1u << d))) continue;
    // The bounce and roulette are the sub-path's own; the light sample is the camera sample's
    // at the first vertex (see PathState).
    bool own = d == bsdf_direction || d == lobe_choice || d == roulette;
    for (int k = 0; k < live_count; ++k) {
      const PathState& path = paths[live[k]];
      lanes.add(own || path.depth > 0 ? path.own : *path.sample,
                dimension(d == roulette ? path.depth + 1 : path.depth, d));
    }
  }
  draw_sample_lanes(paths[live[0]].sample->kind, lanes);  // a render's paths share one sampler
  int group = 0;
  auto next_group = [&](VertexDimension d) { return wants & (1u << d) ? live_count * group++ : -1; };
  int direction = next_group(bsdf_direction), point = next_group(light_point), choice = next_group(light_choice),
      lobe = next_group(lobe_choice), survival = next_group(roulette);
  // The directions warped for diffuse lobes, whichever lobe each path's BSDF will choose: a
  // warp across the lanes costs less than a branch on the lobe would.
  if (direction >= 0)
    cosine_hemisphere_many(lanes.x + direction, lanes.y + direction, live_count, w.cosine_x, w.cosine_y, w.cosine_z);
  for (int k = 0; k < live_count; ++k) {
    VertexDraws& v = w.drawn[k];
    v.drawn = wants;
    v.lobe_choice_used = false;
    v.light_chosen = false;
    if (direction >= 0) {
      v.direction = {lanes.x[direction + k], lanes.y[direction + k]};
      v.cosine = {w.cosine_x[k], w.cosine_y[k], w.cosine_z[k]};
    }
    if (point >= 0) v.light_point = {lanes.x[point + k], lanes.y[point + k]};
    if (choice >= 0) v.light_choice = lanes.x[choice + k];
    if (lobe >= 0) v.lobe_choice = lanes.x[lobe + k];
    if (survival >= 0) v.roulette = lanes.x[survival + k];
  }
}

// The light every live path's vertex would choose by the light BVH, chosen for all of them
// together into its draws: the descents then run side by side, one's steps filling the others'
// waits, where one path at a time each waits on its own chain (docs/lights.md). Only the paths
// that will take a light sample there, as far as is known before their hits are decoded (a
// surface that turns out to be a mirror or see-through wastes its choice).
template <uint32_t E, bool LightSampling>
[[gnu::noinline]] void PathVariant<E, LightSampling>::choose_lights_ahead(const RenderContext& ctx, BatchWorkspace& w, int live_count) {
  LightChoiceQueue& q = w.choices;
  int queued = 0;
  for (int k = 0; k < live_count; ++k) {
    const PathState& path = w.paths[w.live[k]];
    const HitId& id = w.hits[k];
    bool gathers = path.depth > 0 || path.gathers_first_vertex;
    if (!id.valid() || !gathers || path.depth >= path.max_depth || !w.drawn[k].has(light_choice)) continue;
    LightChoicePoint here = light_choice_point(*ctx.accel, path.ray, id);
    q.position[queued] = here.position, q.normal[queued] = here.normal, q.u[queued] = w.drawn[k].light_choice;
    q.draws[queued++] = k;
  }
  choose_lights_by_bvh_many(*ctx.lights, q.position, q.normal, q.u, queued, q.choice, q.found);
  for (int j = 0; j < queued; ++j) {
    VertexDraws& v = w.drawn[q.draws[j]];
    v.light_slot = uint32_t(q.choice[j].slot);
    v.light_probability = q.choice[j].probability;
    v.light_found = q.found[j];
    v.light_chosen = true;
  }
}

// The batch's paths advance a vertex at a time together: each stage's shadow rays, then its
// next rays, are traced as one stream. Each path sees the same values in the same order as
// in run(), so its radiance is run()'s bit for bit. With sub-paths (ctx.split), as many camera
// samples at a time as fill a batch with theirs.
template <uint32_t E, bool LightSampling>
inline void PathVariant<E, LightSampling>::run_batch(const RenderContext& ctx, BatchPath* batch, int count, RayCounts& counts) {
  int camera_samples = max_batch_paths / ctx.split;
  for (int first = 0; first < count; first += camera_samples) {
    int samples = std::min(camera_samples, count - first);
    if (ctx.split > 1)
      run_sub_paths<true>(ctx, batch + first, samples, counts);
    else
      run_sub_paths<false>(ctx, batch + first, samples, counts);
  }
}

// The sub-paths of `count` camera samples (at most max_batch_paths in all), advanced together.
template <uint32_t E, bool LightSampling>
template <bool SharesFirstVertex>
inline void PathVariant<E, LightSampling>::run_sub_paths(const RenderContext& ctx, BatchPath* batch, int count, RayCounts& counts) {
  // One per thread, held by a static object rather than in TLS: a thread's static TLS comes out
  // of its stack, too small for this, and a heap block reached only from TLS looks leaked to
  // LeakSanitizer, which CI runs without scanning TLS (.ci/run).
  static tbb::enumerable_thread_specific<BatchWorkspace> per_thread;
  BatchWorkspace& workspace = per_thread.local();
  auto& [paths, lights, rays, hits, occluded, live, shadowed, scratch, first_vertex, lanes, cosine_x, cosine_y, cosine_z, drawn,
         lobe_choices, first_lobe_choices, light_choices, surface, lane_of, resolved_bsdf, ray_culling] = workspace;
  // Without sharing there is one sub-path per camera sample (run_batch): a constant, the
  // loop below is one start per sample. Read from ctx, GCC vectorised it for any split, with
  // run-time alias checks that cost more per camera sample than the start itself.
  int split = SharesFirstVertex ? ctx.split : 1;
  int live_count = count * split;
  for (int c = 0; c < count; ++c) {
    ++counts.camera;
    for (int sub_path = 0; sub_path < split; ++sub_path) {
      int i = c * split + sub_path;
      start(paths[i], ctx, batch[c].ray, batch[c].sample, sub_path, batch[c].first_hit);
      hits[i] = batch[c].camera_hit;
      live[i] = i;
    }
  }
  lobe_choices = first_lobe_choices;
  for (bool first_stage = true; live_count > 0; first_stage = false) {
    int shadow_count = 0, next_count = 0;
    draw_ahead(ctx, workspace, live_count);
    if (LightSampling && ctx.lights->sampler == LightSampler::bvh) choose_lights_ahead(ctx, workspace, live_count);
    bool in_lanes = false;
    if constexpr (surface_lanes_compiled) {
      // The lanes' light samples always trace. A first stage of sub-paths is all first vertices.
      in_lanes = enabled<E>(ctx.effects, effect_shadows) && !(SharesFirstVertex && first_stage);
      if (in_lanes)
        ctx.phong_lanes ? shade_in_surface_lanes<true>(ctx, workspace, live_count)
                        : shade_in_surface_lanes<false>(ctx, workspace, live_count);
    }
    for (int k = 0; k < live_count; ++k) {
      int i = live[k];
      int lane = in_lanes ? lane_of[k] : -1;
      const SurfaceLanes& set = surface[lane >= 0 ? lane / max_batch_paths : 0];
      lane = lane >= 0 ? lane % max_batch_paths : -1;
      bool goes_on = lane >= 0 && !set.fallback[lane]
                         ? finish_surface_lane(ctx, paths[i], set, lane, hits[k], drawn[k], lights[i], counts)
                         : advance<SharesFirstVertex>(ctx, paths[i], hits[k], &drawn[k], scratch, &first_vertex,
                                                      lights[i], counts);
      if (lights[i].traces) {
        rays[shadow_count] = &lights[i].shadow_ray;
        shadowed[shadow_count++] = i;
      }
      if (goes_on) live[next_count++] = i;  // next_count <= k: live[k] was read already
    }
    lobe_choices = std::any_of(drawn, drawn + live_count, [](const VertexDraws& v) { return v.lobe_choice_used; });
    if (first_stage) first_lobe_choices = lobe_choices;
    if (!(E & effect_group_transparency) || shadows_are_opaque<E>(ctx)) {
      occluded_many(*ctx.accel, rays, shadow_count, occluded, RayCoherence::incoherent);
      for (int k = 0; k < shadow_count; ++k) {
        const LightSampleResult& light = lights[shadowed[k]];
        paths[shadowed[k]].radiance += occluded[k] ? light.blocked : light.unblocked;
      }
    } else {
      // The first segments together; the walks past see-through occluders one at a time.
      // (The stage's hits have all been read.)
      intersect_nearest_many(*ctx.accel, rays, shadow_count, hits, RayCoherence::incoherent);
      for (int k = 0; k < shadow_count; ++k)
        paths[shadowed[k]].radiance += light_past(ctx, lights[shadowed[k]], hits[k], counts);
    }
    for (int k = 0; k < next_count; ++k) {
      PathState& path = paths[live[k]];
      ++(counts.*path.ray_kind);
      rays[k] = &path.ray;
      ray_culling[k] = culling_of(ctx, path);
    }
    intersect_nearest_many(*ctx.accel, rays, next_count, hits, RayCoherence::incoherent, ray_culling);
    live_count = next_count;
  }
  for (int c = 0; c < count; ++c) {
    color3 sum = paths[c * split].radiance;
    for (int sub_path = 1; sub_path < split; ++sub_path) sum = sum + paths[c * split + sub_path].radiance;
    batch[c].radiance = sum;
  }
}

}  // namespace

Integrator select_path(uint32_t effects) { return select_variant<Integrator, PathWithLightSampling>(effects); }
Integrator select_naive(uint32_t effects) { return select_variant<Integrator, PathWithoutLightSampling>(effects); }

}  // namespace radiant
