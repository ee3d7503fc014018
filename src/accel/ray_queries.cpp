// Tracing rays through the accelerator: nearest hits and occlusion, one ray at a time or as
// Embree streams.
#include <algorithm>
#include <cstddef>
#include <cstring>

#include "accel/direct_shapes.h"
#include "accel/embree_callbacks.h"
#include "accel/scene_accel.h"

namespace radiant {

namespace {

// Rays per Embree stream call: a path batch's worth (max_batch_paths), small enough for the stack.
constexpr int stream_length = 256;

// Embree reads a ray's origin and direction as 16-byte blocks, each with its neighbour (tnear,
// time). Written as one block each, the stores forward to those loads; written float by float,
// every traced ray would stall the CPU's store forwarding twice.
//
// Returns whether Embree can trace the ray in every space of `accel` (SceneAccel::
// max_ray_coordinate): checked on the same two blocks, a handful of vector instructions per ray.
bool store_embree_ray(RTCRay& embree_ray, const Ray& ray, const SceneAccel& accel) {
  using float4 = float __attribute__((vector_size(16)));
  using int4 = int __attribute__((vector_size(16)));
  float4 origin = {ray.origin.x, ray.origin.y, ray.origin.z, 0.0f};  // tnear 0
  float4 direction = {ray.direction.x, ray.direction.y, ray.direction.z, ray.time};
  static_assert(offsetof(RTCRay, tnear) == 12 && offsetof(RTCRay, time) == 28);
  std::memcpy(&embree_ray.org_x, &origin, sizeof origin);
  std::memcpy(&embree_ray.dir_x, &direction, sizeof direction);
  embree_ray.tfar = ray.tmax;
  embree_ray.mask = 0xFFFFFFFFu;
  embree_ray.id = 0;
  embree_ray.flags = 0;
  // |v| by clearing the sign bits; a comparison with NaN is false, so NaN fails too.
  const int4 magnitude = {0x7fffffff, 0x7fffffff, 0x7fffffff, 0x7fffffff};
  float bound = accel.max_ray_coordinate;
  float4 origin_bound = {bound, bound, bound, bound}, direction_bound = origin_bound * 2.0f;
  int4 within = ((float4)((int4)origin & magnitude) <= origin_bound) & ((float4)((int4)direction & magnitude) <= direction_bound);
#ifdef __SSE__
  bool all_within = __builtin_ia32_movmskps((float4)within) == 0xF;  // one instruction for the four lanes
#else
  bool all_within = within[0] & within[1] & within[2] & within[3];
#endif
  return all_within && ray.tmax >= 0;
}

// What intersect_nearest reports of Embree's answer for one ray.
HitId hit_of(const SceneAccel& accel, const RTCRayHit& rayhit) {
  HitId id;
  if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return id;
  if (rayhit.hit.instID[0] != RTC_INVALID_GEOMETRY_ID) id.instance = int(rayhit.hit.instID[0]);
  else if (rayhit.hit.geomID == accel.shape_geometry) id.shape = int(rayhit.hit.primID);
  else if (rayhit.hit.geomID >= accel.first_stroke_geometry) id.stroke = int(rayhit.hit.geomID - accel.first_stroke_geometry);
  else id.instance = int(rayhit.hit.geomID);  // a mesh placed in world space on the top level
  id.primitive = rayhit.hit.primID;
  id.t = rayhit.ray.tfar;
  id.barycentric = {rayhit.hit.u, rayhit.hit.v};
  id.geometric_normal_raw = {rayhit.hit.Ng_x, rayhit.hit.Ng_y, rayhit.hit.Ng_z};
  return id;
}

// Counts a ray refused by store_embree_ray (rare: no valid scene casts one).
void count_untraceable(const SceneAccel& accel) { accel.untraceable_rays.fetch_add(1, std::memory_order_relaxed); }

// The intersection context of a query; camera rays in a scene with single-sided meshes take the
// filter that passes their back faces.
RTCIntersectContext query_context(const SceneAccel& accel, RayCoherence coherence, FaceCulling culling) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = coherence == RayCoherence::coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT
                                                      : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
  if (culling == FaceCulling::single_sided_back && accel.has_single_sided) context.filter = cull_single_sided_back_faces;
  return context;
}

}  // namespace

HitId intersect_nearest(const SceneAccel& accel, const Ray& ray, FaceCulling culling) {
  RTCRayHit rayhit;
  if (!store_embree_ray(rayhit.ray, ray, accel)) [[unlikely]] {
    count_untraceable(accel);
    return {};
  }
  if (accel.direct_shapes.enabled)
    return nearest_shape_directly(accel.direct_shapes, accel.scene->shapes, accel.max_ray_coordinate, ray);
  RTCIntersectContext context = query_context(accel, RayCoherence::incoherent, culling);
  rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(accel.top, &context, &rayhit);
  return hit_of(accel, rayhit);
}

bool traces_packets(const SceneAccel& accel) { return !accel.direct_shapes.enabled; }


namespace {

// Streams the rays, those culled and those not apart (one context each); culling_of(i) says
// which ray i is.
template <typename CullingOf>
void intersect_stream(const SceneAccel& accel, const Ray* const* rays, int count, HitId* hits, RayCoherence coherence,
                      CullingOf culling_of) {
  if (!traces_packets(accel)) {
    for (int i = 0; i < count; ++i) hits[i] = intersect_nearest(accel, *rays[i], culling_of(i));
    return;
  }
  RTCRayHit stream[stream_length];
  int traced[stream_length];  // which ray each stream entry is
  for (int i = 0; i < count; ++i) hits[i] = {};
  // Without single-sided meshes no ray is culled: one pass.
  int passes = accel.has_single_sided ? 2 : 1;
  for (int pass = 0; pass < passes; ++pass) {
    FaceCulling culling = pass == 0 ? FaceCulling::none : FaceCulling::single_sided_back;
    RTCIntersectContext context = query_context(accel, coherence, culling);
    for (int begin = 0; begin < count; begin += stream_length) {
      int end = std::min(count, begin + stream_length), length = 0;
      for (int i = begin; i < end; ++i) {
        if (passes == 2 && culling_of(i) != culling) continue;
        RTCRayHit& entry = stream[length];
        if (!store_embree_ray(entry.ray, *rays[i], accel)) [[unlikely]] {
          count_untraceable(accel);
          continue;
        }
        entry.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        entry.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        traced[length++] = i;
      }
      if (length == 0) continue;
      rtcIntersect1M(accel.top, &context, stream, unsigned(length), sizeof(RTCRayHit));
      for (int k = 0; k < length; ++k) hits[traced[k]] = hit_of(accel, stream[k]);
    }
  }
}

}  // namespace

void intersect_nearest_many(const SceneAccel& accel, const Ray* const* rays, int count, HitId* hits,
                            RayCoherence coherence, FaceCulling culling) {
  intersect_stream(accel, rays, count, hits, coherence, [culling](int) { return culling; });
}

void intersect_nearest_many(const SceneAccel& accel, const Ray* const* rays, int count, HitId* hits,
                            RayCoherence coherence, const FaceCulling* culling) {
  intersect_stream(accel, rays, count, hits, coherence, [culling](int i) { return culling[i]; });
}

void occluded_many(const SceneAccel& accel, const Ray* const* rays, int count, bool* occluded, RayCoherence coherence) {
  if (!traces_packets(accel)) {
    for (int i = 0; i < count; ++i) occluded[i] = is_occluded(accel, *rays[i]);
    return;
  }
  RTCRay stream[stream_length];
  int traced[stream_length];
  RTCIntersectContext context = query_context(accel, coherence, FaceCulling::none);
  for (int begin = 0; begin < count; begin += stream_length) {
    int end = std::min(count, begin + stream_length), length = 0;
    for (int i = begin; i < end; ++i) {
      occluded[i] = true;  // what is_occluded says of an untraceable ray
      if (!store_embree_ray(stream[length], *rays[i], accel)) [[unlikely]] {
        count_untraceable(accel);
        continue;
      }
      traced[length++] = i;
    }
    rtcOccluded1M(accel.top, &context, stream, unsigned(length), sizeof(RTCRay));
    for (int k = 0; k < length; ++k) occluded[traced[k]] = stream[k].tfar < 0;
  }
}

bool is_occluded(const SceneAccel& accel, const Ray& ray) {
  RTCRay r;
  if (!store_embree_ray(r, ray, accel)) [[unlikely]] {
    count_untraceable(accel);
    return true;
  }
  if (accel.direct_shapes.enabled)
    return shapes_block_directly(accel.direct_shapes, accel.scene->shapes, accel.max_ray_coordinate, ray);
  RTCIntersectContext context = query_context(accel, RayCoherence::incoherent, FaceCulling::none);
  rtcOccluded1(accel.top, &context, &r);
  return r.tfar < 0;
}


}  // namespace radiant
