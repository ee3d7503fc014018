#include "integrators/path.h"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "integrators/background.h"
#include "integrators/naive.h"
#include "integrators/hit_shading.h"
#include "integrators/surface_lanes.h"
#include "integrators/light_choice_point.h"
#include "integrators/sample_clamp.h"
#include "integrators/shadow.h"
#include "lights/area_light.h"
#include "lights/delta_light.h"
#include "lights/environment_light.h"
#include "lights/light_selection.h"
#include "materials/bsdf.h"
#include "materials/dispersion.h"
#include "sampling/cosine_warp.h"
#include "sampling/sampler.h"
#include "sampling/warp.h"

namespace radiant {

namespace {

// Sample dimensions: 0-1 the pixel, then a fixed block per path vertex, so that switching an
// effect off never shifts the random numbers the others use.
constexpr uint32_t dimensions_per_vertex = 10;
enum VertexDimension : uint32_t {
  light_choice = 0, light_point = 1, lobe_choice = 3, bsdf_direction = 4, roulette = 6, alpha_choice = 7,
  environment_choice = 8, dispersion_channel = 9
};
constexpr uint32_t dimension(int depth, VertexDimension d) { return 2 + uint32_t(depth) * dimensions_per_vertex + d; }
constexpr int roulette_start_depth = 3;

// Emission of an area light at a sampled point (textured emission looked up from the mesh).
template <uint32_t E>
color3 area_light_emission(const RenderContext& ctx, const AreaLight& light, vec2 barycentric) {
  const MaterialDesc& material = ctx.scene->materials[light.material];
  if (!enabled<E>(ctx.effects, effect_textures) || !material.emission_texture.valid() || light.instance < 0)
    return ctx.flat_materials[light.material].emission;
  const MeshDesc& mesh = ctx.scene->meshes[ctx.scene->instances[light.instance].mesh];
  SurfaceAttributes attributes;
  const uint32_t* tri = &mesh.indices[size_t(light.primitive) * 3];
  float b0 = 1 - barycentric.x - barycentric.y;
  for (int set = 0; set < 2; ++set) {
    const auto& uvs = set == 0 ? mesh.texcoords0 : mesh.texcoords1;
    if (!uvs.empty()) attributes.uv[set] = uvs[tri[0]] * b0 + uvs[tri[1]] * barycentric.x + uvs[tri[2]] * barycentric.y;
  }
  return resolve_material(*ctx.scene, material, attributes).emission;
}

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

// Index in the light table of the area light that was hit, or -1.
int hit_light_index(const LightTable& lights, const HitId& id) {
  int area = -1;
  if (id.instance >= 0 && !lights.instance_light_base.empty() && lights.instance_light_base[id.instance] >= 0)
    area = lights.instance_light_base[id.instance] + int(id.primitive);
  else if (id.shape >= 0 && !lights.shape_light.empty())
    area = lights.shape_light[id.shape];
  return area < 0 ? -1 : int(lights.delta_lights.size()) + area;
}

// One light sample's contribution (sample_one_light leaves it before the path's throughput,
// advance scales it). Its shadow ray is left to the caller (`traces`), who may trace it with
// others (the batch traces a stage's together). With opaque shadows the contribution is then `unblocked` or
// `blocked` by the ray's answer; with see-through occluders it is `unblocked` times the light
// let through past them (transmittance_past, walking on towards `target`). Without `traces`,
// `unblocked` is final.
struct LightSampleResult {
  color3 unblocked, blocked;
  Ray shadow_ray;
  // See-through occluders only: where the shadow ray ends (shadow_target), and the vertex's
  // texture footprint scale, for the occluders' textures.
  vec3 target;
  float footprint_scale;
  bool traces = false;
};

// A vertex's random numbers drawn ahead, for a whole batch at once (draw_sample_lanes): the values
// the vertex would draw itself, to the bit (a 1D value is the first of its dimension's pair).
// Those a scene cannot use are not drawn (`has`); run() draws each when it needs it.
struct VertexDraws {
  vec2 direction;      // bsdf_direction
  vec3 cosine;         // sample_cosine_hemisphere(direction), drawn with it
  vec2 light_point;    // light_point
  float light_choice;  // light_choice
  float lobe_choice;   // lobe_choice
  float roulette;      // roulette, of the next vertex (the path's depth + 1; used from its start depth)
  uint32_t drawn = 0;  // the dimensions drawn: a bit (1 << VertexDimension) each
  bool lobe_choice_used = false;  // set by the vertex: whether its BSDF chose a lobe
  // The light chosen ahead by the light BVH, for all of a stage's paths together
  // (choose_lights_ahead): when `light_chosen`, the choice the vertex would make itself, made
  // (`light_found`) or not.
  bool light_chosen = false, light_found = false;
  uint32_t light_slot;
  float light_probability;

  bool has(VertexDimension d) const { return drawn & (1u << d); }
};

// One light sample with MIS against BSDF sampling (next-event estimation) into `out`, as a
// contribution before the path's throughput. `out` is written in place: built elsewhere and
// copied, its ray would stall on store forwarding.
template <uint32_t E>
[[gnu::always_inline]] inline void sample_one_light(const RenderContext& ctx, const SurfaceHit& hit, const Bsdf& bsdf,
                                                    const HitShading& f, const LightChoicePoint& here,
                                                    const SampleContext& sample, int depth, const VertexDraws* drawn,
                                                    RayCounts& counts, LightSampleResult& out) {
  out.traces = false;
  out.unblocked = {};
  const LightTable& lights = *ctx.lights;
  // Random numbers are drawn only when used (one light needs no choice, a delta light no
  // point); their dimensions stay fixed, so skipping one changes no other.
  LightChoice choice;
  auto u_choice = [&] {
    return drawn && drawn->has(light_choice) ? drawn->light_choice : sample_1d(sample, dimension(depth, light_choice));
  };
  auto u_light_point = [&] {
    return drawn && drawn->has(light_point) ? drawn->light_point : sample_2d(sample, dimension(depth, light_point));
  };
  if (drawn && drawn->light_chosen) {
    if (!drawn->light_found) return;
    choice = {drawn->light_slot, drawn->light_probability};
  } else if (!choose_light(lights, here.position, here.normal, u_choice, choice)) {
    return;
  }
  size_t index = choice.slot;
  float select_pdf = choice.probability;

  // The contribution for the shadow ray's transmittance `t`; with opaque shadows both answers
  // are formed now, so that the caller's choice is the value the transmittance would give. Past
  // see-through occluders the caller multiplies the unblocked one by what they let through.
  // `direction` by reference: by value, it came in registers, and the call stored it and read
  // it back as an 8-byte block across two stores, which the CPU cannot forward (a third of the
  // call's time).
  auto finish = [&](const vec3& direction, float distance, auto contribution) {
    out.unblocked = contribution(color3{1, 1, 1});
    if (!enabled<E>(ctx.effects, effect_shadows)) return;
    counts.shadow++;
    if (shadows_are_opaque<E>(ctx))
      out.blocked = contribution(color3{0, 0, 0});
    else
      out.target = shadow_target(hit, direction, distance), out.footprint_scale = texture_footprint_scale(sample.index);
    set_shadow_ray(out.shadow_ray, hit, direction, distance);
    out.traces = true;
  };

  if (index < lights.delta_lights.size()) {
    if (!enabled<E>(ctx.effects, effect_direct_delta)) return;
    DeltaLightSample light;
    if (!sample_delta_light(ctx.scene->lights[lights.delta_lights[index]], hit.position, light)) return;
    color3 f_cos = bsdf.eval(light.direction);
    if (is_black(f_cos)) return;
    return finish(light.direction, light.distance, [&](color3 t) {
      if (is_black(t)) return color3{};
      return f_cos * light.irradiance * t / select_pdf;
    });
  }

  vec3 wi;
  float light_pdf;
  color3 emitted;
  float distance;
  if (index < lights.environment_slot()) {
    if (!enabled<E>(ctx.effects, effect_emission)) return;
    const AreaLight& light = lights.area_lights[index - lights.delta_lights.size()];
    AreaLightSample s;
    vec2 u_point = u_light_point();
    if (!sample_area_light(light, hit.position, u_point, s)) return;
    if (!area_light_emits(light, s.normal, -s.direction)) return;
    wi = s.direction;
    light_pdf = s.pdf;
    distance = s.distance * (1 - 1e-4f);
    emitted = area_light_emission<E>(ctx, light, s.barycentric);
  } else {
    if (!enabled<E>(ctx.effects, effect_environment)) return;
    float u_environment = sample_1d(sample, dimension(depth, environment_choice));
    light_pdf = sample_environment(lights, f.normal, u_environment, u_light_point(), wi);
    if (!(light_pdf > 0)) return;
    distance = std::numeric_limits<float>::infinity();
    emitted = eval_environment(lights, wi);
  }
  if (is_black(emitted)) return;
  float bsdf_pdf;
  color3 f_cos = bsdf.eval(wi, bsdf_pdf);
  if (is_black(f_cos)) return;
  float pdf = select_pdf * light_pdf;
  float weight = power_heuristic(pdf, bsdf_pdf);
  finish(wi, distance, [&](color3 t) {
    if (is_black(t)) return color3{};
    return f_cos * emitted * t * (weight / pdf);
  });
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
                                             LightSampleResult& light, RayCounts& counts) {
    const LightTable& lights = *ctx.lights;
    int depth = path.depth;
    const SampleContext& sample = depth == 0 ? *path.sample : path.own;
    const Ray& ray = path.ray;
    color3& radiance = path.radiance;
    color3& throughput = path.throughput;
    bool gathers = depth > 0 || path.gathers_first_vertex;  // this vertex's own light
    light.traces = false;
    // Beer-Lambert along the segment just traced inside a volume (a ray escaping one, which a
    // closed mesh cannot let happen, keeps its light).
    if (enabled<E>(ctx.effects, effect_absorption) && path.medium >= 0 && id.valid())
      throughput *= exp(ctx.absorption[size_t(path.medium)] * -(id.t * length(ray.direction)));
    if (!id.valid()) {
      // Depth 0 is the camera ray, also after it passed alpha cutouts: it sees the backdrop.
      if (depth == 0) {
        if (gathers) radiance += clamp_contribution(ctx, throughput * camera_background<E>(ctx, ray.direction), -1);
      } else if (gathers && enabled<E>(ctx.effects, effect_environment)) {
        color3 background = eval_environment(lights, normalize(ray.direction));
        float weight = 1;
        // The environment has a selection slot only when it exists (--effects=all can switch
        // the effect on for a scene without one).
        if (LightSampling && !path.specular_bounce && lights.has_environment()) {
          float light_pdf =
              light_choice_probability(lights, path.previous_choice.position, path.previous_choice.normal,
                                       lights.environment_slot()) *
              environment_pdf(lights, path.previous_normal, normalize(ray.direction));
          weight = power_heuristic(path.previous_pdf, light_pdf);
        }
        radiance += clamp_contribution(ctx, throughput * background * weight, depth - 1);
      }
      return false;
    }
    // Only the light BVH rates lights by where they are seen from.
    LightChoicePoint here{};
    if (LightSampling && lights.sampler == LightSampler::bvh) here = light_choice_point(*ctx.accel, ray, id);
    if (SharesFirstVertex && depth == 0) {
      if (!path.gathers_first_vertex && shared->owner == path.sample)
        return scatter_shared(ctx, path, *shared, here, drawn, light, counts);
      if (path.gathers_first_vertex) shared->owner = nullptr;
    }
    SurfaceHit hit = make_surface_hit(*ctx.accel, ray, id);
    const SurfaceMaterial& m = material_at<E>(ctx, id, hit, scratch.resolved, texture_footprint_scale(sample.index));
    if (enabled<E>(ctx.effects, effect_alpha) && m.opacity < 1 &&
        // Each see-through step at this vertex gets its own dimension, far above any vertex's block.
        sample_1d(sample, dimension(depth, alpha_choice) + 0x10000u * uint32_t(path.transparent_steps)) >=
            m.opacity) {
      spawn_ray(path.ray, hit, ray.direction);  // see-through: the path goes on unchanged
      return ++path.transparent_steps < max_see_through_steps;
    }
    HitShading f = make_hit_shading<E>(ctx.effects, hit, m, ray.direction);
    if (path.first_hit && depth == 0) *path.first_hit = {bsdf_albedo(m), f.normal, id.t * length(ray.direction), 1};

    if (gathers && enabled<E>(ctx.effects, effect_emission) && !is_black(m.emission)) {
      const MaterialDesc& authored = ctx.scene->materials[hit.material];
      if (hit.front_face || authored.double_sided) {
        float weight = 1;
        int light_index = hit_light_index(lights, id);
        if (LightSampling && !path.specular_bounce && light_index >= 0) {
          const AreaLight& light = lights.area_lights[light_index - lights.delta_lights.size()];
          float light_pdf =
              light_choice_probability(lights, path.previous_choice.position, path.previous_choice.normal,
                                       size_t(light_index)) *
              area_light_pdf(light, path.previous_position, hit.position, hit.geometric_normal);
          weight = power_heuristic(path.previous_pdf, light_pdf);
        }
        radiance += clamp_contribution(ctx, throughput * m.emission * weight, depth - 1);
      }
    }
    if (m.unlit) {
      if (gathers) radiance += clamp_contribution(ctx, throughput * m.base_color, depth - 1);
      return false;
    }
    // Vertex `depth` gathers light only below max_depth; the emission above completed the
    // direct light of the previous vertex.
    if (depth >= path.max_depth) return false;
    bool dispersive = enabled<E>(ctx.effects, effect_refraction) && m.dispersion > 0 && m.transmission > 0 &&
                      m.model == MaterialModel::metallic_roughness;
    vec3 normal = bsdf_normal(m, f);
    Bsdf bsdf = dispersive ? Bsdf(dispersive_material(m, sample_1d(sample, dimension(depth, dispersion_channel)),
                                                      path.channel, throughput, scratch.dispersed),
                                  normal, f.wo, anisotropy_tangent(hit, m, normal),
                                  enabled<E>(ctx.effects, effect_normal_maps) ? clearcoat_normal(hit, m, normal) : vec3{})
                           : bsdf_at<E>(ctx, hit, m, normal, f.wo);
    // A dispersive first vertex changes each sub-path's throughput and channel: not shared.
    if (SharesFirstVertex && depth == 0 && path.gathers_first_vertex && !dispersive)
      share_first_vertex(path, hit, m, f, bsdf, scratch, *shared);
    return scatter(ctx, path, hit, m, f, bsdf, here, drawn, light, counts);
  }

  static void share_first_vertex(const PathState& path, const SurfaceHit& hit, const SurfaceMaterial& m,
                                 const HitShading& f, const Bsdf& bsdf, const VertexScratch& scratch,
                                 SharedFirstVertex& shared) {
    shared.hit = hit;
    shared.material = &m;
    if (&m == &scratch.resolved) shared.material = &(shared.resolved = m);
    shared.shading = f;
    shared.bsdf = bsdf;
    shared.owner = path.sample;
  }
  // A sub-path at its camera sample's shared first vertex. A function of its own, so that the
  // batch's loop inlines one copy of scatter for both.
  [[gnu::noinline]] static bool scatter_shared(const RenderContext& ctx, PathState& path,
                                               const SharedFirstVertex& shared, const LightChoicePoint& here,
                                               VertexDraws* drawn, LightSampleResult& light, RayCounts& counts) {
    return scatter(ctx, path, shared.hit, *shared.material, shared.shading, *shared.bsdf, here, drawn, light, counts);
  }

  // The rest of a vertex once its hit is shaded: the bounce drawn, the light sample taken (by
  // the path that gathers this vertex's light) and the next ray set.
  [[gnu::always_inline]] static bool scatter(const RenderContext& ctx, PathState& path, const SurfaceHit& hit,
                                             const SurfaceMaterial& m, const HitShading& f, const Bsdf& bsdf,
                                             const LightChoicePoint& here, VertexDraws* drawn,
                                             LightSampleResult& light, RayCounts& counts) {
    int depth = path.depth;
    const SampleContext& sample = depth == 0 ? *path.sample : path.own;
    color3& throughput = path.throughput;
    bool gathers = depth > 0 || path.gathers_first_vertex;
    // The next direction is drawn before the light sample, which does not depend on it: its
    // chain of dependent arithmetic (sampler, warp) then overlaps the shadow ray's traversal
    // in the CPU instead of stalling the next ray. Dimensions are fixed, so the order changes
    // no value.
    float u_lobe = 0.5f;
    if (bsdf.chooses_lobe()) {
      if (drawn) drawn->lobe_choice_used = true;
      u_lobe = drawn && drawn->has(lobe_choice) ? drawn->lobe_choice : sample_1d(path.own, dimension(depth, lobe_choice));
    }
    auto scattered = drawn && drawn->has(bsdf_direction)
                         ? bsdf.sample(u_lobe, drawn->direction, drawn->cosine)
                         : bsdf.sample(u_lobe, sample_2d(path.own, dimension(depth, bsdf_direction)));
    if (LightSampling && gathers && !is_pure_delta(m)) {
      sample_one_light<E>(ctx, hit, bsdf, f, here, sample, depth, drawn, counts, light);
      if (light.traces) {
        light.unblocked = clamp_contribution(ctx, throughput * light.unblocked, depth);
        light.blocked = clamp_contribution(ctx, throughput * light.blocked, depth);
      } else {
        path.radiance += clamp_contribution(ctx, throughput * light.unblocked, depth);
      }
    }
    if (!scattered || is_black(scattered->weight)) return false;
    // Without indirect light a diffuse or glossy bounce only completes this vertex's direct light.
    if (!scattered->delta && !enabled<E>(ctx.effects, effect_indirect))
      path.max_depth = std::min(path.max_depth, depth + 1);
    if (scattered->delta) {
      bool refracted = scattered->transmitted;
      if (refracted && !enabled<E>(ctx.effects, effect_refraction)) return false;
      // A transmissive surface's mirror share (Fresnel, total internal reflection) belongs to
      // refraction: switching reflection off must not make glass lose it.
      bool transmissive = !is_black(m.kt) || m.transmission > 0;
      if (!refracted && !transmissive && !enabled<E>(ctx.effects, effect_reflection)) return false;
      path.ray_kind = refracted ? &RayCounts::refraction : &RayCounts::reflection;
    } else {
      path.ray_kind = &RayCounts::indirect;
    }
    // Crossing a surface enters its volume from the front and leaves it from the back.
    if (enabled<E>(ctx.effects, effect_absorption) && scattered->transmitted)
      path.medium = hit.front_face && !is_black(ctx.absorption[size_t(hit.material)]) ? hit.material : -1;
    throughput *= depth == 0 ? scattered->weight * path.split_weight : scattered->weight;
    path.specular_bounce = scattered->delta;
    path.previous_pdf = scattered->pdf;
    path.previous_position = hit.position;
    path.previous_normal = f.normal;
    if (LightSampling && ctx.lights->sampler == LightSampler::bvh) path.previous_choice = here;
    spawn_ray(path.ray, hit, scattered->wi);
    path.depth = ++depth;
    if (depth >= roulette_start_depth) {
      // A sub-path's share (split_weight) is not a loss of light: roulette goes by its whole.
      float survive = std::min(1.0f, max_component(throughput) * path.split);
      float u = drawn && drawn->has(roulette) ? drawn->roulette : sample_1d(path.own, dimension(depth, roulette));
      if (u >= survive) return false;
      throughput /= survive;
    }
    return true;
  }

  // Sub-path `sub_path` of a camera sample at its camera ray, set field by field in place (see
  // sample_one_light): the batch's workspace reuses its states. AOV values come from the first.
  // Not inlined: in the batch's loop over camera samples GCC's -O3 loop distribution split its
  // two dozen stores into as many loops, each walking all the path states for one field (about
  // 100 instructions a camera sample of loop control, and the states streamed 28 times).
  [[gnu::noinline]] static void start(PathState& path, const RenderContext& ctx, const Ray& camera_ray,
                                      const SampleContext& sample, int sub_path, FirstHit* first_hit) {
    path.radiance = {};
    path.throughput = {1, 1, 1};
    path.ray_kind = &RayCounts::camera;
    path.specular_bounce = true;
    path.previous_pdf = 0;
    path.depth = 0;
    path.transparent_steps = 0;
    path.medium = -1;
    path.channel = -1;
    path.ray.origin = camera_ray.origin;
    path.ray.direction = camera_ray.direction;
    path.ray.tmax = camera_ray.tmax;
    path.ray.time = camera_ray.time;
    path.sample = &sample;
    // One aggregate: copied and then given its index in a second store, GCC 12 at -O3 (not -O2,
    // nor with -fno-strict-aliasing) lost the index store in the batch's inlined copy, and every
    // sub-path drew the first one's numbers (tests/render/indirect_paths_test.cpp catches it).
    path.own = {sample.kind, sample.pixel, sample.index * uint32_t(ctx.split) + uint32_t(sub_path), sample.samples,
                sample.seed};
    path.gathers_first_vertex = sub_path == 0;
    path.split = float(ctx.split);
    path.split_weight = 1.0f / float(ctx.split);
    path.first_hit = sub_path == 0 ? first_hit : nullptr;
    path.max_depth = ctx.max_depth;
  }

  // A light sample's contribution past see-through occluders, its shadow ray's first segment
  // traced to `first` (invalid: nothing in between).
  static color3 light_past(const RenderContext& ctx, const LightSampleResult& light, const HitId& first,
                           RayCounts& counts) {
    return light.unblocked *
           transmittance_past<E>(ctx, light.shadow_ray, first, light.target, false, light.footprint_scale, counts);
  }

  // One path at a time (its sub-paths one after another, summed in order, each shading the first
  // vertex itself): the reference the batch must match.
  static color3 run(const RenderContext& ctx, const Ray& camera_ray, const SampleContext& sample, RayCounts& counts,
                    FirstHit* first_hit, const HitId* camera_hit) {
    ++counts.camera;
    HitId first = camera_hit ? *camera_hit : intersect_nearest(*ctx.accel, camera_ray, camera_culling(ctx));
    VertexScratch scratch;
    LightSampleResult light;
    color3 sum;
    for (int sub_path = 0; sub_path < ctx.split; ++sub_path) {
      PathState path;
      start(path, ctx, camera_ray, sample, sub_path, first_hit);
      HitId id = first;
      for (;;) {
        bool goes_on = advance<false>(ctx, path, id, nullptr, scratch, nullptr, light, counts);
        if (light.traces)
          path.radiance += shadows_are_opaque<E>(ctx)
                               ? (is_occluded(*ctx.accel, light.shadow_ray) ? light.blocked : light.unblocked)
                               : light_past(ctx, light, intersect_nearest(*ctx.accel, light.shadow_ray), counts);
        if (!goes_on) break;
        ++(counts.*path.ray_kind);
        id = intersect_nearest(*ctx.accel, path.ray, culling_of(ctx, path));
      }
      sum = sub_path == 0 ? path.radiance : sum + path.radiance;
    }
    return sum;
  }

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
  [[gnu::noinline]] static void shade_in_surface_lanes(const RenderContext& ctx, BatchWorkspace& w, int live_count) {
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
  static RenderContext::LaneModel resolve_lane_vertex(const RenderContext& ctx, const PathState& path,
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

  static void set_triangle_hit(SurfaceLanes& l, int i, const MeshDesc& mesh, const SceneAccel& accel, const HitId& id) {
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
  static void set_shape_hit(SurfaceLanes& l, int i, const ShapeDesc& shape, const Ray& ray, const HitId& id) {
    l.hit_kinds |= SurfaceLanes::shape_hits;
    l.shape[i] = shape.kind == ShapeKind::sphere ? SurfaceLanes::sphere_hit : SurfaceLanes::plane_hit;
    l.normals[i] = SurfaceLanes::no_normals, l.transformed[i] = 0;
    l.ray_ox[i] = ray.origin.x, l.ray_oy[i] = ray.origin.y, l.ray_oz[i] = ray.origin.z, l.ray_t[i] = id.t;
    l.center_x[i] = shape.center.x, l.center_y[i] = shape.center.y, l.center_z[i] = shape.center.z;
    l.radius[i] = shape.radius;
    l.axis_x[i] = shape.axis.x, l.axis_y[i] = shape.axis.y, l.axis_z[i] = shape.axis.z;
  }
  static void set_instance_transform(SurfaceLanes& l, int i, const SceneAccel& accel, int instance) {
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
  static float glossy_lobe_choice(const MetallicRoughnessParams& p, const PathState& path, VertexDraws& drawn) {
    bool specular = p.metal > 0 || p.plastic * p.specular > 0;
    if (!(specular && has_cosine_lobes(p))) return 0.5f;
    drawn.lobe_choice_used = true;
    return drawn.has(lobe_choice) ? drawn.lobe_choice : sample_1d(path.own, dimension(path.depth, lobe_choice));
  }

  // A Phong lane's material, lobe choice and bounce numbers. Out of line: inlined, it made the
  // gather dearer for every vertex, Lambert ones too (callgrind, .scene box: 0.24 M of its 14.4 M).
  [[gnu::noinline]] static void set_phong_lane(SurfaceLanes& l, int i, const PhongWeights& w, const PathState& path,
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
  [[gnu::always_inline]] static bool finish_surface_lane(const RenderContext& ctx, PathState& path,
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

  // Every live path's random numbers for the vertex it is at, drawn together in SIMD, a group
  // of lanes per dimension: those its scene can use (a light point only with area or
  // environment lights, a light choice only with one to make, roulette once a path can reach
  // its start depth). Every sampler: a `.scene` file's jittered sampler keeps its pixel
  // positions in path mode, and its vertices draw hashes that run in lanes as well as Sobol's.
  // At least one path is live.
  [[gnu::always_inline]] static void draw_ahead(const RenderContext& ctx, BatchWorkspace& w, int live_count) {
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
  [[gnu::noinline]] static void choose_lights_ahead(const RenderContext& ctx, BatchWorkspace& w, int live_count) {
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
  static void run_batch(const RenderContext& ctx, BatchPath* batch, int count, RayCounts& counts) {
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
  template <bool SharesFirstVertex>
  static void run_sub_paths(const RenderContext& ctx, BatchPath* batch, int count, RayCounts& counts) {
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
};

template <uint32_t E>
using PathWithLightSampling = PathVariant<E, true>;
template <uint32_t E>
using PathWithoutLightSampling = PathVariant<E, false>;

}  // namespace

Integrator select_path(uint32_t effects) { return select_variant<Integrator, PathWithLightSampling>(effects); }
Integrator select_naive(uint32_t effects) { return select_variant<Integrator, PathWithoutLightSampling>(effects); }

}  // namespace radiant
