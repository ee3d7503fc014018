#include "accel/embree_callbacks.h"

#include <limits>

#include "accel/accel_structure.h"
#include "accel/analytic_shapes.h"
#include "materials/surface.h"
#include "scene/shape_bounds.h"

namespace radiant {

namespace {

const SceneAccel& accel_of(void* user) { return *static_cast<const SceneAccel*>(user); }

}  // namespace

void shape_bounds_callback(const RTCBoundsFunctionArguments* args) {
  const SceneAccel& accel = accel_of(args->geometryUserPtr);
  vec3 lower, upper;
  // Planes and tubes are infinite; Embree needs finite boxes: they end where rays may reach.
  shape_bounds(accel.scene->shapes[args->primID], accel.max_ray_coordinate, lower, upper);
  *args->bounds_o = {lower.x, lower.y, lower.z, 0, upper.x, upper.y, upper.z, 0};
}

namespace {

// Ray i of a packet of N (1, 4, 8 or 16 rays, in Embree's structure-of-arrays layout): Embree
// calls back with packets when it traces streams, with one ray when it traces one.
template <unsigned N>
Ray packet_ray(RTCRayN* rays, unsigned i) {
  return {{RTCRayN_org_x(rays, N, i), RTCRayN_org_y(rays, N, i), RTCRayN_org_z(rays, N, i)},
          {RTCRayN_dir_x(rays, N, i), RTCRayN_dir_y(rays, N, i), RTCRayN_dir_z(rays, N, i)},
          RTCRayN_tfar(rays, N, i)};
}

// Each valid ray is crossed with the shape on its own, in the same double-precision arithmetic
// whatever the packet, so a stream finds the hits single rays find.
template <unsigned N>
void intersect_shape_packet(const RTCIntersectFunctionNArguments* args) {
  const SceneAccel& accel = accel_of(args->geometryUserPtr);
  const ShapeDesc& shape = accel.scene->shapes[args->primID];
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, N);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, N);
  for (unsigned i = 0; i < N; ++i) {
    if (!args->valid[i]) continue;
    Ray ray = packet_ray<N>(rays, i);
    ShapeCrossing crossing;
    if (!cross_shape(shape, ray, RTCRayN_tnear(rays, N, i), crossing) ||
        !shape_hit_in_range(accel.max_ray_coordinate, ray, crossing.t))
      continue;
    ShapeHit hit = complete_shape_hit(shape, ray, crossing);
    RTCRayN_tfar(rays, N, i) = hit.t;
    RTCHitN_geomID(hits, N, i) = args->geomID;
    RTCHitN_primID(hits, N, i) = args->primID;
    RTCHitN_Ng_x(hits, N, i) = hit.normal.x;
    RTCHitN_Ng_y(hits, N, i) = hit.normal.y;
    RTCHitN_Ng_z(hits, N, i) = hit.normal.z;
    RTCHitN_u(hits, N, i) = hit.uv.x;
    RTCHitN_v(hits, N, i) = hit.uv.y;
    RTCHitN_instID(hits, N, i, 0) = args->context->instID[0];
  }
}

template <unsigned N>
void occlude_shape_packet(const RTCOccludedFunctionNArguments* args) {
  const SceneAccel& accel = accel_of(args->geometryUserPtr);
  const ShapeDesc& shape = accel.scene->shapes[args->primID];
  for (unsigned i = 0; i < N; ++i) {
    if (!args->valid[i]) continue;
    Ray ray = packet_ray<N>(args->ray, i);
    ShapeCrossing crossing;
    if (cross_shape(shape, ray, RTCRayN_tnear(args->ray, N, i), crossing) &&
        shape_hit_in_range(accel.max_ray_coordinate, ray, crossing.t))
      RTCRayN_tfar(args->ray, N, i) = -std::numeric_limits<float>::infinity();
  }
}

// Each packet size compiled on its own: with N known, a ray's fields are fixed offsets, and a
// single ray (most of a Whitted render's) costs what it cost before packets were taken (with N
// read at run time, a showcase render's callbacks took 2x the instructions).
template <typename Arguments, void (*Packet1)(const Arguments*), void (*Packet4)(const Arguments*),
          void (*Packet8)(const Arguments*), void (*Packet16)(const Arguments*)>
void by_packet_size(const Arguments* args) {
  switch (args->N) {
    case 1: return Packet1(args);
    case 4: return Packet4(args);
    case 8: return Packet8(args);
    case 16: return Packet16(args);
  }
}

}  // namespace

void shape_intersect_callback(const RTCIntersectFunctionNArguments* args) {
  by_packet_size<RTCIntersectFunctionNArguments, intersect_shape_packet<1>, intersect_shape_packet<4>,
                 intersect_shape_packet<8>, intersect_shape_packet<16>>(args);
}

void shape_occluded_callback(const RTCOccludedFunctionNArguments* args) {
  by_packet_size<RTCOccludedFunctionNArguments, occlude_shape_packet<1>, occlude_shape_packet<4>,
                 occlude_shape_packet<8>, occlude_shape_packet<16>>(args);
}

namespace {

}  // namespace

void alpha_mask_filter(const RTCFilterFunctionNArguments* args) {
  const auto* filter = static_cast<const SceneAccel::MeshFilter*>(args->geometryUserPtr);
  const SceneDesc& scene = *filter->accel->scene;
  const MeshDesc& mesh = scene.meshes[filter->mesh];
  const MaterialDesc& material = scene.materials[mesh.material];
  const unsigned N = args->N;
  for (unsigned i = 0; i < N; ++i) {
    if (args->valid[i] == 0) continue;
    uint32_t prim = RTCHitN_primID(args->hit, N, i);
    float u = RTCHitN_u(args->hit, N, i), v = RTCHitN_v(args->hit, N, i);
    const uint32_t* tri = &mesh.indices[size_t(prim) * 3];
    SurfaceAttributes attributes;
    float b0 = 1 - u - v;
    if (!mesh.texcoords0.empty())
      attributes.uv[0] = mesh.texcoords0[tri[0]] * b0 + mesh.texcoords0[tri[1]] * u + mesh.texcoords0[tri[2]] * v;
    if (!mesh.texcoords1.empty())
      attributes.uv[1] = mesh.texcoords1[tri[0]] * b0 + mesh.texcoords1[tri[1]] * u + mesh.texcoords1[tri[2]] * v;
    float alpha = material.alpha;
    if (material.base_color_texture.valid())
      alpha *= sample_texture(scene, material.base_color_texture, attributes, true).w;
    if (material.alpha_texture.valid()) alpha *= sample_texture(scene, material.alpha_texture, attributes, false).x;
    if (!mesh.colors.empty())
      alpha *= mesh.colors[tri[0]].w * b0 + mesh.colors[tri[1]].w * u + mesh.colors[tri[2]].w * v;
    if (alpha < material.alpha_cutoff) args->valid[i] = 0;
  }
}

void cull_single_sided_back_faces(const RTCFilterFunctionNArguments* args) {
  const auto* filter = static_cast<const SceneAccel::MeshFilter*>(args->geometryUserPtr);
  if (!filter || !filter->single_sided) return;
  // In an instance Embree hands over the ray and Ng in object space, where a mirroring transform
  // turns which side the ray meets; a mesh on the top level is in world space.
  unsigned instance = args->context->instID[0];
  float orientation = instance == RTC_INVALID_GEOMETRY_ID ? 1.0f : filter->accel->instance_orientation[instance];
  const unsigned N = args->N;
  for (unsigned i = 0; i < N; ++i) {
    if (args->valid[i] == 0) continue;
    vec3 direction = {RTCRayN_dir_x(args->ray, N, i), RTCRayN_dir_y(args->ray, N, i), RTCRayN_dir_z(args->ray, N, i)};
    vec3 normal = {RTCHitN_Ng_x(args->hit, N, i), RTCHitN_Ng_y(args->hit, N, i), RTCHitN_Ng_z(args->hit, N, i)};
    if (!arrives_on_front(direction, normal, orientation)) args->valid[i] = 0;
  }
}

}  // namespace radiant
