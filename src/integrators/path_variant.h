// The path tracer compiled for a scene's effects `E`, with light sampling (path) or without
// (naive): one path at a time (run, the reference) and batches of paths (run_batch). Its
// parts: the vertex (path_vertex.h), the surface lanes' gather and scatter (path_lanes.h) and
// the batch driver (path.cpp); light sampling is path_light_sample.h.
#pragma once

#include "integrators/path_state.h"

namespace radiant {

// Internal to the path integrator: included by path.cpp alone.
namespace {

template <uint32_t E, bool LightSampling>
struct PathVariant {
  // The path's vertex at `id`, the hit of path.ray: adds what it sees, takes a light sample
  // (its shadow ray left in `light` when light.traces) and sets the next ray. Returns whether
  // the path goes on along path.ray. `drawn`, when given, holds random numbers drawn ahead.
  // With `SharesFirstVertex` a camera sample's sub-paths share its first vertex's shading through
  // `shared` (ctx.split > 1); compiled apart so that one path per camera sample pays nothing.
  template <bool SharesFirstVertex>
  [[gnu::always_inline]] static bool advance(const RenderContext& ctx, PathState& path, const HitId& id,
                                             VertexDraws* drawn, VertexScratch& scratch, SharedFirstVertex* shared,
                                             LightSampleResult& light, RayCounts& counts);

  static void share_first_vertex(const PathState& path, const SurfaceHit& hit, const SurfaceMaterial& m,
                                 const HitShading& f, const Bsdf& bsdf, const VertexScratch& scratch,
                                 SharedFirstVertex& shared);
  // A sub-path at its camera sample's shared first vertex. A function of its own, so that the
  // batch's loop inlines one copy of scatter for both.
  [[gnu::noinline]] static bool scatter_shared(const RenderContext& ctx, PathState& path,
                                               const SharedFirstVertex& shared, const LightChoicePoint& here,
                                               VertexDraws* drawn, LightSampleResult& light, RayCounts& counts);

  // The rest of a vertex once its hit is shaded: the bounce drawn, the light sample taken (by
  // the path that gathers this vertex's light) and the next ray set.
  [[gnu::always_inline]] static bool scatter(const RenderContext& ctx, PathState& path, const SurfaceHit& hit,
                                             const SurfaceMaterial& m, const HitShading& f, const Bsdf& bsdf,
                                             const LightChoicePoint& here, VertexDraws* drawn,
                                             LightSampleResult& light, RayCounts& counts);

  // Sub-path `sub_path` of a camera sample at its camera ray, set field by field in place (see
  // sample_one_light): the batch's workspace reuses its states. AOV values come from the first.
  // Not inlined: in the batch's loop over camera samples GCC's -O3 loop distribution split its
  // two dozen stores into as many loops, each walking all the path states for one field (about
  // 100 instructions a camera sample of loop control, and the states streamed 28 times).
  [[gnu::noinline]] static void start(PathState& path, const RenderContext& ctx, const Ray& camera_ray,
                                      const SampleContext& sample, int sub_path, FirstHit* first_hit);

  // A light sample's contribution past see-through occluders, its shadow ray's first segment
  // traced to `first` (invalid: nothing in between).
  static color3 light_past(const RenderContext& ctx, const LightSampleResult& light, const HitId& first,
                           RayCounts& counts);

  // One path at a time (its sub-paths one after another, summed in order, each shading the first
  // vertex itself): the reference the batch must match.
  static color3 run(const RenderContext& ctx, const Ray& camera_ray, const SampleContext& sample, RayCounts& counts,
                    FirstHit* first_hit, const HitId* camera_hit);

  // What a batch keeps per path, allocated once per thread: constructing it for every batch
  // (the member initialisers) was a measurable share of the batch's time.
  struct BatchWorkspace {
    PathState paths[max_batch_paths];
    LightSampleResult lights[max_batch_paths];
    const Ray* rays[max_batch_paths];
    HitId hits[max_batch_paths];
    bool occluded[max_batch_paths];
    int live[max_batch_paths], shadowed[max_batch_paths];
    VertexScratch scratch;
    SharedFirstVertex first_vertex;  // with sub-paths
    // A stage's draws (draw_ahead): the sampler's lanes, the directions' cosine warps, each live
    // path's values, and whether the last stage's BSDFs chose lobes (then this one draws their
    // choices ahead too). A batch's first stage goes by the previous batch's first stage: the
    // last stage before it, a few long paths deep, says little about the camera's hits. Either
    // guess only decides where the numbers are drawn, never their values.
    SampleLanes lanes;
    float cosine_x[max_batch_paths], cosine_y[max_batch_paths], cosine_z[max_batch_paths];
    VertexDraws drawn[max_batch_paths];
    bool lobe_choices = true, first_lobe_choices = true;
    // A stage's light choices by the BVH (choose_lights_ahead): the points, normals and numbers
    // of the paths that take a light sample, which live path each is, and the choices.
    LightChoiceQueue choices;
    // A stage's vertices shaded in the surface lanes (shade_in_surface_lanes), a set per model
    // (Lambert, glossy, Phong: the LaneModel less one), and each live path's lane: -1, or its
    // set times max_batch_paths plus its lane in the set.
    SurfaceLanes surface[3]{};  // zeroed: a lane's unused fields are read, never chosen
    int lane_of[max_batch_paths];
    std::optional<BsdfMaterial> resolved_bsdf;  // a textured candidate's (resolve_lane_vertex)
    FaceCulling ray_culling[max_batch_paths];   // each next ray's (culling_of)
  };

  // Whether this variant can shade vertices in the surface lanes. Textured variants resolve each
  // candidate's material at its hit first (resolve_lane_vertex); where surfaces are seen
  // through, the lanes take the opaque ones and the batch walks their shadow rays past
  // see-through occluders (light_past).
  static constexpr bool surface_lanes_compiled = LightSampling;

  // Gathers the stage's vertices that the surface lanes can shade (surface_lanes.h) and shades
  // them: a live path at a hit of a mesh's triangle, a sphere or a plane, whose material is a lane material,
  // which chooses a point, spot or directional light, an emitting triangle or sphere, or
  // the environment. Its light is chosen, a triangle's point drawn and a glossy material's lobe
  // choice drawn here, as the one-path code would.
  // `PhongLanes` (ctx.phong_lanes): compiled without the Phong lanes, the gather of a scene that
  // has none costs what it did before they existed (about 1% of the Lambert box's instructions).
  template <bool PhongLanes>
  [[gnu::noinline]] static void shade_in_surface_lanes(const RenderContext& ctx, BatchWorkspace& w, int live_count);

  // A textured render's candidate for the lanes (shade_in_surface_lanes): its material resolved
  // at the hit as advance() resolves it, into `bsdf`, and the lanes it can go to, if any. Where a
  // normal or bump map bends the shading normal, `mapped_normal` is advance()'s (HitShading's
  // authored normal), which the lanes then use instead of their own.
  static RenderContext::LaneModel resolve_lane_vertex(const RenderContext& ctx, const PathState& path,
                                                      const HitId& id, const SampleContext& sample,
                                                      VertexScratch& scratch, std::optional<BsdfMaterial>& bsdf,
                                                      std::optional<vec3>& mapped_normal);

  static void set_triangle_hit(SurfaceLanes& l, int i, const MeshDesc& mesh, const SceneAccel& accel, const HitId& id);
  // A sphere's or a plane's hit (fill_shape_hit): no vertex normals, no transform.
  static void set_shape_hit(SurfaceLanes& l, int i, const ShapeDesc& shape, const Ray& ray, const HitId& id);
  static void set_instance_transform(SurfaceLanes& l, int i, const SceneAccel& accel, int instance);
  // The lobe choice a glossy vertex draws (scatter): only where its BSDF mixes lobes, which a
  // lane material's does wherever its lobes are valid if it has both a specular and a diffuse
  // lobe (elsewhere the vertex does not scatter, and the choice is not read).
  static float glossy_lobe_choice(const MetallicRoughnessParams& p, const PathState& path, VertexDraws& drawn);

  // A Phong lane's material, lobe choice and bounce numbers. Out of line: inlined, it made the
  // gather dearer for every vertex, Lambert ones too (callgrind, .scene box: 0.24 M of its 14.4 M).
  [[gnu::noinline]] static void set_phong_lane(SurfaceLanes& l, int i, const PhongWeights& w, const PathState& path,
                                               VertexDraws& drawn);

  // The rest of advance() for a vertex shaded in lane `i`: the light sample's result, the path's
  // state and its next ray, as advance() sets them.
  [[gnu::always_inline]] static bool finish_surface_lane(const RenderContext& ctx, PathState& path,
                                                        const SurfaceLanes& l, int i, const HitId& id,
                                                        const VertexDraws& drawn, LightSampleResult& light,
                                                        RayCounts& counts);

  // Every live path's random numbers for the vertex it is at, drawn together in SIMD, a group
  // of lanes per dimension: those its scene can use (a light point only with area or
  // environment lights, a light choice only with one to make, roulette once a path can reach
  // its start depth). Every sampler: a `.scene` file's jittered sampler keeps its pixel
  // positions in path mode, and its vertices draw hashes that run in lanes as well as Sobol's.
  // At least one path is live.
  [[gnu::always_inline]] static void draw_ahead(const RenderContext& ctx, BatchWorkspace& w, int live_count);

  // The light every live path's vertex would choose by the light BVH, chosen for all of them
  // together into its draws: the descents then run side by side, one's steps filling the others'
  // waits, where one path at a time each waits on its own chain (docs/lights.md). Only the paths
  // that will take a light sample there, as far as is known before their hits are decoded (a
  // surface that turns out to be a mirror or see-through wastes its choice).
  [[gnu::noinline]] static void choose_lights_ahead(const RenderContext& ctx, BatchWorkspace& w, int live_count);

  // The batch's paths advance a vertex at a time together: each stage's shadow rays, then its
  // next rays, are traced as one stream. Each path sees the same values in the same order as
  // in run(), so its radiance is run()'s bit for bit. With sub-paths (ctx.split), as many camera
  // samples at a time as fill a batch with theirs.
  static void run_batch(const RenderContext& ctx, BatchPath* batch, int count, RayCounts& counts);

  // The sub-paths of `count` camera samples (at most max_batch_paths in all), advanced together.
  template <bool SharesFirstVertex>
  static void run_sub_paths(const RenderContext& ctx, BatchPath* batch, int count, RayCounts& counts);
};

template <uint32_t E>
using PathWithLightSampling = PathVariant<E, true>;
template <uint32_t E>
using PathWithoutLightSampling = PathVariant<E, false>;

}  // namespace

}  // namespace radiant
