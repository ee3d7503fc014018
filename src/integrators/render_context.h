// What every integrator reads while tracing: the scene, its acceleration structure, the lights,
// resolved settings, and per-thread ray counters.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "accel/scene_accel.h"
#include "integrators/effect_variants.h"
#include "lights/light_table.h"
#include "materials/bsdf.h"
#include "materials/surface.h"
#include "materials/texture_footprint.h"
#include "sampling/sampler.h"
#include "scene/effects.h"
#include "scene/scene_desc.h"

namespace radiant {

// The most partly opaque surfaces a path sees through. A stack of alpha-blended cards can be
// deep, and a see-through step does not count as a bounce: without a bound, Whitted's recursion
// through them could exhaust the stack. What lies beyond the last step is taken as black.
constexpr int max_see_through_steps = 256;

struct RayCounts {
  uint64_t camera = 0, shadow = 0, reflection = 0, refraction = 0, indirect = 0;
  uint64_t nonfinite_samples = 0;
  uint64_t total() const { return camera + shadow + reflection + refraction + indirect; }
  RayCounts& operator+=(const RayCounts& o) {
    camera += o.camera, shadow += o.shadow, reflection += o.reflection, refraction += o.refraction;
    indirect += o.indirect, nonfinite_samples += o.nonfinite_samples;
    return *this;
  }
};

// First-hit values for the albedo, normal and depth AOVs, and the coverage of a transparent
// render: 1 where the camera ray met geometry (what an alpha cutout lets through does not count),
// 0 where it saw the background; a fraction where Whitted blends a partly opaque surface.
struct FirstHit {
  color3 albedo;
  vec3 normal;
  float depth = 0;
  float coverage = 0;
};
inline bool is_finite(const FirstHit& hit) {
  return is_finite(hit.albedo) && is_finite(hit.normal) && std::isfinite(hit.depth);
}

// What a camera ray that leaves the scene sees: the environment, its blurred backdrop, a
// colour, or nothing (a transparent render, whose alpha says where the scene is).
enum class CameraBackground : uint8_t { environment, backdrop, color, none };

struct RenderContext {
  const SceneDesc* scene = nullptr;
  const SceneAccel* accel = nullptr;
  const LightTable* lights = nullptr;
  color3 ambient;                              // sum of the ambient lights
  std::vector<SurfaceMaterial> flat_materials; // each material resolved once, for untextured renders
  std::vector<BsdfMaterial> flat_bsdf_materials;  // and its BSDF's direction-independent part
  std::vector<color3> absorption;                 // each material's volume sigma (KHR_materials_volume)
  // Per material: which of the path tracer's surface lanes can shade a vertex on it as it is
  // without textures (integrators/surface_lanes.h, lane_model_of), if any. A textured render
  // asks again at each hit on the materials this lets in.
  enum class LaneModel : uint8_t { none, lambert, glossy, phong };
  std::vector<LaneModel> lane_models;
  // Whether any material can resolve to the Phong lanes (a Phong model with ks): only then is the
  // batch's gather compiled with them (path.cpp).
  bool phong_lanes = false;
  TextureLookup texture_lookup;  // --texture-filter and its pyramids
  PixelSpread pixel_spread;      // the camera's, for texture footprints (trilinear only)
  uint32_t effects = effect_all;
  int max_depth = 8;
  // Paths that leave each camera sample's first hit (--indirect-paths; path tracing only): the
  // first hit's own light is gathered once, its bounce sampled this many times, each 1/split.
  int split = 1;
  float contribution_cutoff = 0.001f;
  // Cycles' sample clamps (integrators/sample_clamp.h; 0 = off): the light gathered at a path's
  // first hit, and at its later vertices.
  float clamp_direct = 0, clamp_indirect = 0;
  // What camera rays that escape see (--background); the environment still lights what they
  // hit, and is seen in reflections and through glass.
  CameraBackground camera_background = CameraBackground::environment;
  color3 background_color;  // for CameraBackground::color
};

// How camera rays meet faces: past the back faces of single-sided materials when the scene calls
// for it (accel/scene_accel.h, FaceCulling).
inline FaceCulling camera_culling(const RenderContext& ctx) {
  return (ctx.effects & effect_single_sided) ? FaceCulling::single_sided_back : FaceCulling::none;
}

// Radiance along a camera ray for one sample; `first_hit` (optional) receives AOV values.
// `camera_hit` (optional) is the ray's nearest hit, already traced with its neighbours'
// (intersect_nearest_many); without it the integrator traces the ray itself.
using RadianceFunction = color3 (*)(const RenderContext& ctx, const Ray& ray, const SampleContext& sample,
                                    RayCounts& counts, FirstHit* first_hit, const HitId* camera_hit);

// The material at hit `id`: resolved into `resolved` when textures or normal maps are on (both
// read texels, filtered over `footprint_scale` times the pixel's footprint there:
// texture_footprint_scale), otherwise the one resolved once per render (no copy per hit).
template <uint32_t E>
const SurfaceMaterial& material_at(const RenderContext& ctx, const HitId& id, SurfaceHit& hit,
                                   SurfaceMaterial& resolved, float footprint_scale) {
  if (enabled<E>(ctx.effects, effect_textures) || enabled<E>(ctx.effects, effect_normal_maps)) {
    if (ctx.texture_lookup.mode == TextureFilterMode::trilinear) {
      vec3 dpdx, dpdy;
      approximate_dp_dxy(ctx.pixel_spread, hit.position, hit.geometric_normal, dpdx, dpdy);
      set_uv_footprint(*ctx.accel, id, dpdx * footprint_scale, dpdy * footprint_scale, hit);
    }
    hit.attributes.lookup = &ctx.texture_lookup;
    return resolved = resolve_material(*ctx.scene, ctx.scene->materials[hit.material], hit.attributes);
  }
  return ctx.flat_materials[hit.material];
}

// The world direction of an anisotropic material's lobe (KHR_materials_anisotropy): its
// tangent-space direction in the hit's tangent frame (bitangent cross(n, t) * w, as normal maps);
// zero without anisotropy or tangents.
inline vec3 anisotropy_tangent(const SurfaceHit& hit, const SurfaceMaterial& m, vec3 n) {
  if (!(m.anisotropy > 0)) return {};
  vec3 t = {hit.tangent.x, hit.tangent.y, hit.tangent.z};
  if (length_squared(t) == 0) return {};
  return t * m.anisotropy_direction.x + cross(n, t) * (hit.tangent.w * m.anisotropy_direction.y);
}

// A clearcoat's own shading normal (KHR_materials_clearcoat), on the side of `n`: the vertex
// normal, bent by the coat's normal map in the base map's tangent frame. Zero (the coat shares
// `n`) without a coat, or when neither the base nor the coat is normal- or bump-mapped.
inline vec3 clearcoat_normal(const SurfaceHit& hit, const SurfaceMaterial& m, vec3 n) {
  if (!(m.clearcoat > 0) || !(m.has_clearcoat_normal_map || m.has_normal_map || m.has_bump_map)) return {};
  vec3 c = hit.shading_normal;
  if (m.has_clearcoat_normal_map && (hit.tangent.x != 0 || hit.tangent.y != 0 || hit.tangent.z != 0))
    c = apply_normal_map(c, hit.tangent, m.clearcoat_normal_sample);
  return dot(hit.shading_normal, n) < 0 ? -c : c;
}

// The BSDF at a hit for material `m` (from material_at), seen from wo with shading normal `n`.
template <uint32_t E>
Bsdf bsdf_at(const RenderContext& ctx, const SurfaceHit& hit, const SurfaceMaterial& m, vec3 n, vec3 wo) {
  vec3 tangent = anisotropy_tangent(hit, m, n);
  if (enabled<E>(ctx.effects, effect_normal_maps)) return Bsdf(m, n, wo, tangent, clearcoat_normal(hit, m, n));
  if (enabled<E>(ctx.effects, effect_textures)) return Bsdf(m, n, wo, tangent);
  return Bsdf(ctx.flat_bsdf_materials[hit.material], n, wo, tangent);
}

// One path of a batch: its camera ray with the hit already traced, its sample, where its AOV
// values go (optional), and the radiance it returns.
struct BatchPath {
  Ray ray;
  HitId camera_hit;
  SampleContext sample;
  FirstHit* first_hit = nullptr;
  color3 radiance;
};
// The most paths one batch holds: four samples each of a tile of 8 x 8 pixels. One sample's 64
// paths left Embree's stream packets a few rays per octant of direction; four samples' fill them
// better (about 6% less time than one on the Cornell box). Eight gained nothing more.
constexpr int batch_tile_pixels = 64;
constexpr int batch_samples = 4;
constexpr int max_batch_paths = batch_tile_pixels * batch_samples;
// Radiance along `count` camera rays (at most max_batch_paths) whose hits are already traced.
// Each path's radiance is the RadianceFunction's for it, bit for bit; an integrator may advance
// them together and trace their rays as streams.
using BatchRadianceFunction = void (*)(const RenderContext& ctx, BatchPath* paths, int count, RayCounts& counts);

// An integrator compiled for one effect set: one path at a time (the reference), and a batch.
struct Integrator {
  RadianceFunction one_path;
  BatchRadianceFunction batch;
};

// A batch run one path at a time from its camera hit.
inline void run_each_path(RadianceFunction one_path, const RenderContext& ctx, BatchPath* paths, int count,
                          RayCounts& counts) {
  for (int i = 0; i < count; ++i) {
    BatchPath& p = paths[i];
    p.radiance = one_path(ctx, p.ray, p.sample, counts, p.first_hit, &p.camera_hit);
  }
}

}  // namespace radiant
