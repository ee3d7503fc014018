// What a path carries from vertex to vertex (PathState), and the per-thread scratch a vertex
// and a batch of paths share.
#pragma once

#include <optional>

#include "integrators/path_light_sample.h"

namespace radiant {

// Internal to the path integrator: included by path.cpp alone.
namespace {

// KHR_materials_dispersion by a hero channel: from its first dispersive surface on, a path
// carries one colour channel (chosen uniformly, weight 3) and refracts with that channel's
// wavelength's IOR. Returns the material to shade with: `m`, or `dispersed` with its IOR set.
const SurfaceMaterial& dispersive_material(const SurfaceMaterial& m, float u_channel, int& channel, color3& throughput,
                                           SurfaceMaterial& dispersed) {
  if (channel < 0) {
    channel = std::min(2, int(3 * u_channel));
    color3 only_channel;
    only_channel[channel] = 3;
    throughput *= only_channel;
  }
  dispersed = m;
  dispersed.ior = dispersive_ior(m.ior, m.dispersion, channel_wavelengths_nm[channel]);
  return dispersed;
}

// A path between two vertices: everything its loop carries from one hit to the next.
// PathVariant::start sets every field; previous_* are read only after a bounce wrote them.
//
// With --indirect-paths (ctx.split > 1) a camera sample's path branches at its first hit into
// `split` sub-paths, each run as a path of its own from the same camera hit. The first hit's
// own light (what it emits, its light sample, the background where the camera ray escapes) is
// gathered by the first sub-path alone; every sub-path samples its own bounce there and carries
// 1/split of it. So the first vertex's numbers other than the bounce (the light sample, alpha,
// dispersion) are the camera sample's (`sample`), shared by its sub-paths; the bounce's and
// every later vertex's are the sub-path's own (`own`, sample index index * split + its number),
// which are `sample`'s when split is 1.
struct PathState {
  Ray ray;  // the ray just traced, or about to be
  color3 radiance, throughput;
  const SampleContext* sample;
  SampleContext own;
  bool gathers_first_vertex;  // the first sub-path of its camera sample
  float split, split_weight;  // ctx.split and 1 / ctx.split
  FirstHit* first_hit;
  uint64_t RayCounts::*ray_kind;  // the kind of `ray`, counted when traced
  bool specular_bounce;
  float previous_pdf;
  vec3 previous_position, previous_normal;
  // Where the previous vertex chose its light; set by the light BVH's vertices only (power
  // sampling's MIS reads it and ignores it, so it is set once, when the state is made).
  LightChoicePoint previous_choice{};
  int depth, max_depth;
  int transparent_steps;
  int medium;   // the absorbing volume the path is inside (a material index), or -1
  int channel;  // the colour channel the path carries after a dispersive surface, or -1
};

// How the path's next ray meets faces: a camera ray that went on past see-through surfaces is
// still the camera's, and passes single-sided back faces as it did.
inline FaceCulling culling_of(const RenderContext& ctx, const PathState& path) {
  return path.ray_kind == &RayCounts::camera ? camera_culling(ctx) : FaceCulling::none;
}

// A camera sample's first vertex as its first sub-path shaded it, for the other sub-paths
// (--indirect-paths): they see the same hit of the same ray with the same numbers, so decoding
// it and building its BSDF again would give the same values. Valid for `owner`'s sub-paths: the
// first clears it before it shades its vertex (again after each see-through step, which all of
// them take alike) and fills it after. The batch shares it (one per thread, in its workspace);
// run(), the reference, does not.
struct SharedFirstVertex {
  const SampleContext* owner = nullptr;
  SurfaceHit hit;
  const SurfaceMaterial* material = nullptr;  // the scene's, or `resolved`
  SurfaceMaterial resolved;  // a textured material's copy: any other path's vertex reuses the scratch's
  HitShading shading;
  std::optional<Bsdf> bsdf;
};

// The light choices a batch's stage makes together (PathVariant::choose_lights_ahead).
struct LightChoiceQueue {
  vec3 position[max_batch_paths], normal[max_batch_paths];
  float u[max_batch_paths];
  int draws[max_batch_paths];  // the live path's index in the stage (its VertexDraws)
  LightChoice choice[max_batch_paths];
  bool found[max_batch_paths];
};

// Materials resolved at one vertex (one per thread, reused: they are large).
struct VertexScratch {
  SurfaceMaterial resolved;   // the material at the hit, when textured
  SurfaceMaterial dispersed;  // and with its channel's IOR
};

}  // namespace

}  // namespace radiant
