// Building, updating and querying the accelerator (accel/accel_structure.h): nearest hits,
// occlusion, hit decoding and the rays spawned from a hit.
#pragma once

#include <embree3/rtcore.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "accel/accel_structure.h"
#include "accel/direct_shapes.h"
#include "accel/hit_id.h"
#include "accel/ray.h"
#include "accel/stroke_geometry.h"
#include "materials/surface.h"
#include "scene/scene_changes.h"
#include "scene/scene_desc.h"

namespace radiant {

// How the top level is built. `single_level`: one BVH over every triangle placed there, the
// fastest to trace. `two_level`: Embree's low-quality scene build, a BVH of per-geometry BVHs,
// so that an update rebuilds only the geometries that changed (an animation's frames). Both
// find the same hits; only which of two surfaces hit at exactly the same distance can differ.
enum class AccelLayout { single_level, two_level };

// Builds the acceleration structure; `scene` must outlive it. Throws std::runtime_error when
// Embree reports an error, or when an instance shrinks space so much that the scene's extent
// would leave Embree's range in its object space.
// `strokes` sizes the lines and points (their radii are fixed at build time).
std::unique_ptr<SceneAccel> build_scene_accel(const SceneDesc& scene, AccelLayout layout = AccelLayout::single_level,
                                              const StrokeSizing& strokes = {});

// Brings the accelerator up to date after accel.scene changed in place by `changes` only
// (scene/scene_changes.h): moved instances get their new transforms or vertices, deformed meshes
// new vertices, an instance whose transform turned exact (or stopped being) is laid out anew as
// a build would lay it out, and Embree rebuilds those geometries alone when the layout is
// two-level (the single-level one rebuilds its whole BVH). Throws as a build.
void update_scene_accel(SceneAccel& accel, const SceneChanges& changes);

// Which faces a ray meets. Camera rays pass through the back faces of single-sided materials, as
// glTF's doubleSided false asks (the back face is not seen); shadow rays and bounces meet every
// face, so that a closed single-sided mesh still casts shadows and holds light in.
enum class FaceCulling : uint8_t { none, single_sided_back };

// Nearest hit along the ray (from t = 0 to ray.tmax); none for an untraceable ray.
HitId intersect_nearest(const SceneAccel& accel, const Ray& ray, FaceCulling culling = FaceCulling::none);
// Whether intersect_nearest_many and occluded_many trace streams here (otherwise they trace ray
// by ray: a scene of a few shapes traced without Embree). Analytic shapes and alpha masks,
// which Embree calls back for, take its packets.
bool traces_packets(const SceneAccel& accel);
// How the rays of one call relate: a tile's camera rays travel together, and Embree sorts them
// into packets; the bounces and shadow rays of different paths mostly do not.
enum class RayCoherence { coherent, incoherent };
// The nearest hits of `count` rays traced as one stream, which costs less per ray than one at a
// time. Each hit is the one intersect_nearest gives for its ray. The rays are read where they
// lie (copying a freshly written ray stalls on store forwarding).
void intersect_nearest_many(const SceneAccel& accel, const Ray* const* rays, int count, HitId* hits,
                            RayCoherence coherence, FaceCulling culling = FaceCulling::none);
// The same with each ray's own culling: culling[i] for *rays[i].
void intersect_nearest_many(const SceneAccel& accel, const Ray* const* rays, int count, HitId* hits,
                            RayCoherence coherence, const FaceCulling* culling);
// is_occluded for `count` rays traced as one stream: occluded[i] for *rays[i].
void occluded_many(const SceneAccel& accel, const Ray* const* rays, int count, bool* occluded, RayCoherence coherence);
// True when anything blocks the ray before ray.tmax, or when the ray is untraceable.
bool is_occluded(const SceneAccel& accel, const Ray& ray);

// Everything about a hit point the integrators need, in world space.
struct SurfaceHit {
  vec3 position;
  vec3 position_error;    // per-axis bound on the rounding error of `position`
  vec3 geometric_normal;  // unit; the authored front side
  vec3 shading_normal;    // unit; interpolated (and later normal-mapped) on the same side
  vec4 tangent = {0, 0, 0, 0};  // xyz world tangent, w handedness; zero when absent
  vec3 dpdu, dpdv;  // world position per unit of texcoords0 u and v; only for bump-mapped materials
  SurfaceAttributes attributes;
  int material = -1;
  bool front_face = true;  // the ray arrived on the geometric normal's side
  float time = 0;          // the time of the ray that found it: rays leaving it travel then too
};

// Decoded where the ray met it: a moving instance or deforming mesh at the ray's time.
SurfaceHit make_surface_hit(const SceneAccel& accel, const Ray& ray, const HitId& id);

// Whether hit `id` lies on a mesh that moves or deforms while the shutter is open, so that only
// make_surface_hit, at the ray's time, places it (not the rendered pose).
inline bool moves_during_shutter(const SceneAccel& accel, const HitId& id) {
  if (id.instance < 0) return false;
  const InstanceDesc& instance = accel.scene->instances[size_t(id.instance)];
  return !instance.motion.empty() || !accel.scene->meshes[size_t(instance.mesh)].motion_positions.empty();
}

// Sets hit.attributes' uv footprint (duv_dx, duv_dy of each uv set) from the position footprint
// dpdx, dpdy at a triangle hit, by least squares in the triangle's plane (pbrt-v4's
// ComputeDifferentials); analytic shapes keep none (they carry no textures).
void set_uv_footprint(const SceneAccel& accel, const HitId& id, vec3 dpdx, vec3 dpdy, SurfaceHit& hit);

// The spawn functions come in two forms: returning the ray, and writing it into `ray` field by
// field. Assigning a returned Ray to an existing one copies it through a temporary with wide
// loads that stall on store forwarding (the pieces were just stored narrower), which costs the
// batched integrator, whose path state lives in memory, a tenth of its time.

// A ray leaving `hit` in `direction`, with its origin offset by the error bound.
[[gnu::always_inline]] inline void spawn_ray(Ray& ray, const SurfaceHit& hit, vec3 direction) {
  ray.origin = offset_ray_origin(hit.position, hit.position_error, hit.geometric_normal, direction);
  ray.direction = direction;
  ray.tmax = std::numeric_limits<float>::infinity();
  ray.time = hit.time;
}
inline Ray spawn_ray(const SurfaceHit& hit, vec3 direction) {
  Ray ray;
  spawn_ray(ray, hit, direction);
  return ray;
}
// A ray from `hit` towards `target`, ending just short of it (for shadow rays).
[[gnu::always_inline]] inline void spawn_ray_to(Ray& ray, const SurfaceHit& hit, vec3 target) {
  vec3 direction = target - hit.position;
  vec3 origin = offset_ray_origin(hit.position, hit.position_error, hit.geometric_normal, direction);
  ray.origin = origin;
  ray.direction = target - origin;
  ray.tmax = 1 - 1e-4f;
  ray.time = hit.time;
}
inline Ray spawn_ray_to(const SurfaceHit& hit, vec3 target) {
  Ray ray;
  spawn_ray_to(ray, hit, target);
  return ray;
}

}  // namespace radiant
