#include "accel/scene_accel.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "accel/analytic_shapes.h"
#include "accel/direct_shapes.h"
#include "accel/embree_isa.h"
#include "scene/coordinate_range.h"

namespace radiant {

namespace {

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
  float4 direction = {ray.direction.x, ray.direction.y, ray.direction.z, 0.0f};  // time 0
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
  else id.instance = int(rayhit.hit.geomID);  // a mesh placed in world space on the top level
  id.primitive = rayhit.hit.primID;
  id.t = rayhit.ray.tfar;
  id.barycentric = {rayhit.hit.u, rayhit.hit.v};
  id.geometric_normal_raw = {rayhit.hit.Ng_x, rayhit.hit.Ng_y, rayhit.hit.Ng_z};
  return id;
}

// Counts a ray refused by store_embree_ray (rare: no valid scene casts one).
void count_untraceable(const SceneAccel& accel) { accel.untraceable_rays.fetch_add(1, std::memory_order_relaxed); }

struct DeviceError {
  std::string message;
};

void record_device_error(void* user, RTCError code, const char* message) {
  auto* error = static_cast<DeviceError*>(user);
  if (error->message.empty())
    error->message = "Embree error " + std::to_string(int(code)) + ": " + (message ? message : "");
}

DeviceError& device_error() {
  static thread_local DeviceError error;
  return error;
}

void throw_on_device_error() {
  DeviceError& e = device_error();
  if (!e.message.empty()) {
    std::string m = e.message;
    e.message.clear();
    throw std::runtime_error(m);
  }
}

const SceneAccel& accel_of(void* user) { return *static_cast<const SceneAccel*>(user); }

void shape_bounds_callback(const RTCBoundsFunctionArguments* args) {
  const SceneAccel& accel = accel_of(args->geometryUserPtr);
  vec3 lower, upper;
  // Planes and tubes are infinite; Embree needs finite boxes: they end where rays may reach.
  shape_bounds(accel.scene->shapes[args->primID], accel.max_ray_coordinate, lower, upper);
  *args->bounds_o = {lower.x, lower.y, lower.z, 0, upper.x, upper.y, upper.z, 0};
}

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

void shape_intersect_callback(const RTCIntersectFunctionNArguments* args) {
  by_packet_size<RTCIntersectFunctionNArguments, intersect_shape_packet<1>, intersect_shape_packet<4>,
                 intersect_shape_packet<8>, intersect_shape_packet<16>>(args);
}

void shape_occluded_callback(const RTCOccludedFunctionNArguments* args) {
  by_packet_size<RTCOccludedFunctionNArguments, occlude_shape_packet<1>, occlude_shape_packet<4>,
                 occlude_shape_packet<8>, occlude_shape_packet<16>>(args);
}

// Rejects hits on texels whose alpha is under the material's cutoff, so they are never hit.
void alpha_mask_filter(const RTCFilterFunctionNArguments* args) {
  const auto* mask = static_cast<const SceneAccel::AlphaMask*>(args->geometryUserPtr);
  const SceneDesc& scene = *mask->scene;
  const MeshDesc& mesh = scene.meshes[mask->mesh];
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

// What hit decoding needs of instance i's transform: its inverse, orientation and identity.
void record_instance_transform(SceneAccel& accel, int i) {
  const mat4& transform = accel.scene->instances[i].transform;
  if (!inverse_affine(transform, accel.instance_inverse[i]))
    throw std::runtime_error("instances[" + std::to_string(i) + "]: singular transform");
  accel.instance_orientation[i] = determinant3(transform) < 0 ? -1.0f : 1.0f;
  accel.instance_identity[i] = is_identity(transform);
}

// A mesh's vertices placed by `transform`, in double precision; false unless every coordinate
// is exactly a float, so that placing the mesh in world space does not move it at all.
bool place_exactly(const MeshDesc& mesh, const mat4& transform, std::vector<vec3>& placed) {
  placed.resize(mesh.positions.size());
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    vec3 p = mesh.positions[i];
    for (int r = 0; r < 3; ++r) {
      const float* row = transform.m[r];
      double exact = double(row[0]) * p.x + double(row[1]) * p.y + double(row[2]) * p.z + double(row[3]);
      placed[i][r] = float(exact);
      if (double(placed[i][r]) != exact) return false;
    }
  }
  return true;
}

void write_vertices(float* vertices, const std::vector<vec3>& positions) {
  for (size_t i = 0; i < positions.size(); ++i) {
    vertices[3 * i + 0] = positions[i].x;
    vertices[3 * i + 1] = positions[i].y;
    vertices[3 * i + 2] = positions[i].z;
  }
}

// Gives a committed triangle geometry new vertex positions (as many as it had).
void replace_vertices(RTCGeometry geometry, const std::vector<vec3>& positions) {
  write_vertices(static_cast<float*>(rtcGetGeometryBufferData(geometry, RTC_BUFFER_TYPE_VERTEX, 0)), positions);
  rtcUpdateGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0);
  rtcCommitGeometry(geometry);
}

// A triangle geometry of a mesh with the given vertex positions; alpha-masked materials get the
// filter that lets rays pass through cut-out texels.
RTCGeometry new_triangle_geometry(SceneAccel& accel, int mesh_index, const std::vector<vec3>& positions) {
  const MeshDesc& mesh = accel.scene->meshes[mesh_index];
  RTCGeometry geometry = rtcNewGeometry(accel.device, RTC_GEOMETRY_TYPE_TRIANGLE);
  write_vertices(static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                             3 * sizeof(float), positions.size())),
                 positions);
  auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), mesh.triangle_count()));
  std::copy(mesh.indices.begin(), mesh.indices.begin() + 3 * mesh.triangle_count(), indices);
  if (mesh.material >= 0 && accel.scene->materials[mesh.material].alpha_mode == AlphaMode::mask) {
    rtcSetGeometryUserData(geometry, &accel.alpha_masks[mesh_index]);
    rtcSetGeometryIntersectFilterFunction(geometry, alpha_mask_filter);
    rtcSetGeometryOccludedFilterFunction(geometry, alpha_mask_filter);
  }
  rtcCommitGeometry(geometry);
  return geometry;
}

RTCScene build_mesh_scene(SceneAccel& accel, int mesh_index) {
  RTCScene scene = rtcNewScene(accel.device);
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  RTCGeometry geometry = new_triangle_geometry(accel, mesh_index, accel.scene->meshes[mesh_index].positions);
  rtcAttachGeometryByID(scene, geometry, 0);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene);
  return scene;
}

void set_instance_transform(RTCGeometry geometry, const mat4& transform) {
  float rows[12];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) rows[r * 4 + c] = transform.m[r][c];
  rtcSetGeometryTransform(geometry, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, rows);
}

// Instance i's top-level geometry: its mesh's triangles at `world_positions` when `flat`, else an
// instance of the mesh's own scene (built on first use).
RTCGeometry new_placed_geometry(SceneAccel& accel, int i, bool flat, const std::vector<vec3>& world_positions) {
  const InstanceDesc& instance = accel.scene->instances[i];
  if (flat) return new_triangle_geometry(accel, instance.mesh, world_positions);
  if (!accel.mesh_scenes[instance.mesh]) accel.mesh_scenes[instance.mesh] = build_mesh_scene(accel, instance.mesh);
  RTCGeometry geometry = rtcNewGeometry(accel.device, RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(geometry, accel.mesh_scenes[instance.mesh]);
  set_instance_transform(geometry, instance.transform);
  rtcCommitGeometry(geometry);
  return geometry;
}

// How many instances place each mesh: a mesh placed once may sit flat on the top level.
std::vector<int> mesh_placements(const SceneDesc& scene) {
  std::vector<int> placements(scene.meshes.size(), 0);
  for (const InstanceDesc& instance : scene.instances) ++placements[instance.mesh];
  return placements;
}

// Attaches every instance; records in accel.instanced those traced through an object space of
// their own.
void attach_instances(SceneAccel& accel) {
  const SceneDesc& scene = *accel.scene;
  // A mesh placed once joins the top level in world space when its transform moves every vertex
  // to an exact float (identity, translations and scalings that fit): rounding the vertices
  // instead would move the surface (a translation by 1e6 rounds them to 1/16), opening the
  // cracks and leaks the stability tests catch; an instance keeps the exact object space.
  std::vector<int> placements = mesh_placements(scene);
  accel.mesh_scenes.assign(scene.meshes.size(), nullptr);
  std::vector<vec3> world_positions;
  accel.instance_inverse.resize(scene.instances.size());
  accel.instance_orientation.resize(scene.instances.size());
  accel.instance_identity.resize(scene.instances.size());
  accel.instanced.clear();
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    const InstanceDesc& instance = scene.instances[i];
    record_instance_transform(accel, int(i));
    bool flat = placements[instance.mesh] == 1 && place_exactly(scene.meshes[instance.mesh], instance.transform, world_positions);
    if (!flat) accel.instanced.push_back(int(i));
    RTCGeometry geometry = new_placed_geometry(accel, int(i), flat, world_positions);
    rtcAttachGeometryByID(accel.top, geometry, unsigned(i));
    rtcReleaseGeometry(geometry);
  }
}

// How much an instance shrinks space into its object space: the row-sum norm of its inverse,
// which bounds |object-space coordinate| / |render-space coordinate|.
double object_space_growth(const mat4& inverse) {
  double largest = 0;
  for (int r = 0; r < 3; ++r)
    largest = std::max(largest, double(std::abs(inverse.m[r][0])) + std::abs(inverse.m[r][1]) + std::abs(inverse.m[r][2]));
  return largest;
}

// The bounding box of a mesh's object-space vertices (lower > upper when it has none).
std::pair<vec3, vec3> mesh_box(const MeshDesc& mesh) {
  constexpr float inf = std::numeric_limits<float>::infinity();
  vec3 lower = {inf, inf, inf}, upper = -lower;
  for (vec3 p : mesh.positions) lower = min(lower, p), upper = max(upper, p);
  return {lower, upper};
}

// The largest coordinate magnitude of a box's corners placed by `transform`.
double placed_reach(const std::pair<vec3, vec3>& box, const mat4& transform) {
  auto [lower, upper] = box;
  if (!(lower.x <= upper.x)) return 0;
  double reach = 0;
  for (int corner = 0; corner < 8; ++corner) {
    vec3 p = {corner & 1 ? upper.x : lower.x, corner & 2 ? upper.y : lower.y, corner & 4 ? upper.z : lower.z};
    reach = std::max(reach, double(max_component(abs(transform_point(transform, p)))));
  }
  return reach;
}

// Sets the traceable range from the instances' object spaces: a ray within it, transformed by
// any instance's inverse, stays within max_traced_coordinate (origin and translation both within
// the range, so twice the growth). Refuses a scene whose own extent does not fit.
void set_traceable_range(SceneAccel& accel) {
  const SceneDesc& scene = *accel.scene;
  const std::vector<int>& instanced = accel.instanced;
  double growth = 1;
  int shrinking = -1;
  for (int i : instanced) {
    double g = object_space_growth(accel.instance_inverse[i]);
    if (g > growth) growth = g, shrinking = i;
  }
  accel.max_ray_coordinate = float(max_traced_coordinate / (2 * growth));
  if (shrinking < 0) return;  // validation keeps render space far inside the full range
  std::vector<std::pair<vec3, vec3>> boxes;
  boxes.reserve(scene.meshes.size());
  for (const MeshDesc& mesh : scene.meshes) boxes.push_back(mesh_box(mesh));
  double reach = 0;
  for (const InstanceDesc& instance : scene.instances)
    reach = std::max(reach, placed_reach(boxes[instance.mesh], instance.transform));
  for (int i : instanced) {  // the translation enters the object-space origin as well
    const mat4& m = scene.instances[i].transform;
    reach = std::max(reach, double(max_component(abs(vec3{m.m[0][3], m.m[1][3], m.m[2][3]}))));
  }
  for (const ShapeDesc& shape : scene.shapes) {
    if (shape.kind == ShapeKind::plane || shape.kind == ShapeKind::tube) continue;
    vec3 lower, upper;
    shape_bounds(shape, 0, lower, upper);
    reach = std::max({reach, double(max_component(abs(lower))), double(max_component(abs(upper)))});
  }
  if (reach > 0.5 * accel.max_ray_coordinate) {
    const std::string& name = scene.instances[shrinking].name;
    char text[192];
    std::snprintf(text, sizeof text,
                  ": its transform shrinks space by %g, too much for a scene reaching %g from the camera (rays would "
                  "leave Embree's range in its object space)",
                  1 / growth, reach);
    throw std::runtime_error(scene.source_path + ": instances[" + std::to_string(shrinking) + "]" +
                             (name.empty() ? "" : " '" + name + "'") + text);
  }
}

void attach_shapes(SceneAccel& accel) {
  if (accel.scene->shapes.empty()) return;
  RTCGeometry geometry = rtcNewGeometry(accel.device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geometry, unsigned(accel.scene->shapes.size()));
  rtcSetGeometryUserData(geometry, &accel);
  rtcSetGeometryBoundsFunction(geometry, shape_bounds_callback, nullptr);
  rtcSetGeometryIntersectFunction(geometry, shape_intersect_callback);
  rtcSetGeometryOccludedFunction(geometry, shape_occluded_callback);
  rtcCommitGeometry(geometry);
  accel.shape_geometry = unsigned(accel.scene->instances.size());
  rtcAttachGeometryByID(accel.top, geometry, accel.shape_geometry);
  rtcReleaseGeometry(geometry);
}

}  // namespace

SceneAccel::~SceneAccel() {
  for (RTCScene s : mesh_scenes)
    if (s) rtcReleaseScene(s);
  if (top) rtcReleaseScene(top);
  if (device) rtcReleaseDevice(device);
}

std::unique_ptr<SceneAccel> build_scene_accel(const SceneDesc& scene, AccelLayout layout) {
  auto accel = std::make_unique<SceneAccel>();
  accel->scene = &scene;
  accel->device = rtcNewDevice(embree_device_config().c_str());
  if (!accel->device) throw std::runtime_error("cannot create the Embree device");
  rtcSetDeviceErrorFunction(accel->device, record_device_error, &device_error());
  accel->alpha_masks.resize(scene.meshes.size());
  for (size_t m = 0; m < scene.meshes.size(); ++m) accel->alpha_masks[m] = {&scene, int(m)};
  accel->top = rtcNewScene(accel->device);
  if (layout == AccelLayout::two_level) {
    // DYNAMIC keeps the per-geometry builders after a commit, so the next one reuses their BVHs.
    rtcSetSceneFlags(accel->top, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_DYNAMIC);
    rtcSetSceneBuildQuality(accel->top, RTC_BUILD_QUALITY_LOW);
  } else {
    rtcSetSceneFlags(accel->top, RTC_SCENE_FLAG_ROBUST);
  }
  attach_instances(*accel);
  set_traceable_range(*accel);
  attach_shapes(*accel);
  accel->direct_shapes = direct_shapes_of(scene);
  rtcCommitScene(accel->top);
  throw_on_device_error();
  return accel;
}

void update_scene_accel(SceneAccel& accel, const SceneChanges& changes) {
  const SceneDesc& scene = *accel.scene;
  std::vector<int> placements = mesh_placements(scene);
  std::vector<char> instanced(scene.instances.size(), 0), mesh_updated(scene.meshes.size(), 0);
  for (int i : accel.instanced) instanced[i] = 1;
  std::vector<vec3> world_positions;
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    const InstanceDesc& instance = scene.instances[i];
    bool deformed = changes.deformed_meshes[instance.mesh], moved = changes.moved_instances[i];
    if (!deformed && !moved) continue;
    const MeshDesc& mesh = scene.meshes[instance.mesh];
    record_instance_transform(accel, int(i));
    bool flat = placements[instance.mesh] == 1 && place_exactly(mesh, instance.transform, world_positions);
    RTCScene mesh_scene = accel.mesh_scenes[instance.mesh];
    if (deformed && mesh_scene && !mesh_updated[instance.mesh]) {  // kept current even while unused
      replace_vertices(rtcGetGeometry(mesh_scene, 0), mesh.positions);
      rtcCommitScene(mesh_scene);
      mesh_updated[instance.mesh] = 1;
    }
    bool same_layout = flat != bool(instanced[i]);
    if (same_layout) {
      RTCGeometry geometry = rtcGetGeometry(accel.top, unsigned(i));
      if (flat) replace_vertices(geometry, world_positions);
      else set_instance_transform(geometry, instance.transform), rtcCommitGeometry(geometry);
      continue;
    }
    // Laid out the other way now (its transform turned exact, or stopped being): as a new build
    // would lay it out, so that the frame is the image a render of it alone gives.
    instanced[i] = !flat;
    RTCGeometry geometry = new_placed_geometry(accel, int(i), flat, world_positions);
    rtcDetachGeometry(accel.top, unsigned(i));
    rtcAttachGeometryByID(accel.top, geometry, unsigned(i));
    rtcReleaseGeometry(geometry);
  }
  accel.instanced.clear();
  for (size_t i = 0; i < instanced.size(); ++i)
    if (instanced[i]) accel.instanced.push_back(int(i));
  if (changes.shapes_changed && accel.shape_geometry != RTC_INVALID_GEOMETRY_ID) {
    rtcCommitGeometry(rtcGetGeometry(accel.top, accel.shape_geometry));  // its bounds are read again
    accel.direct_shapes = direct_shapes_of(scene);
  }
  set_traceable_range(accel);
  rtcCommitScene(accel.top);
  throw_on_device_error();
}

HitId intersect_nearest(const SceneAccel& accel, const Ray& ray) {
  RTCRayHit rayhit;
  if (!store_embree_ray(rayhit.ray, ray, accel)) [[unlikely]] {
    count_untraceable(accel);
    return {};
  }
  if (accel.direct_shapes.enabled) return nearest_shape_directly(accel, ray);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(accel.top, &context, &rayhit);
  return hit_of(accel, rayhit);
}

bool traces_packets(const SceneAccel& accel) { return !accel.direct_shapes.enabled; }

namespace {
// Rays per Embree stream call: a path batch's worth (max_batch_paths), small enough for the stack.
constexpr int stream_length = 256;

RTCIntersectContext stream_context(RayCoherence coherence) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = coherence == RayCoherence::coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT
                                                      : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
  return context;
}
}  // namespace

void intersect_nearest_many(const SceneAccel& accel, const Ray* const* rays, int count, HitId* hits,
                            RayCoherence coherence) {
  if (!traces_packets(accel)) {
    for (int i = 0; i < count; ++i) hits[i] = intersect_nearest(accel, *rays[i]);
    return;
  }
  RTCRayHit stream[stream_length];
  int traced[stream_length];  // which ray each stream entry is
  RTCIntersectContext context = stream_context(coherence);
  for (int begin = 0; begin < count; begin += stream_length) {
    int end = std::min(count, begin + stream_length), length = 0;
    for (int i = begin; i < end; ++i) {
      hits[i] = {};
      RTCRayHit& entry = stream[length];
      if (!store_embree_ray(entry.ray, *rays[i], accel)) [[unlikely]] {
        count_untraceable(accel);
        continue;
      }
      entry.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      entry.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      traced[length++] = i;
    }
    rtcIntersect1M(accel.top, &context, stream, unsigned(length), sizeof(RTCRayHit));
    for (int k = 0; k < length; ++k) hits[traced[k]] = hit_of(accel, stream[k]);
  }
}

void occluded_many(const SceneAccel& accel, const Ray* const* rays, int count, bool* occluded, RayCoherence coherence) {
  if (!traces_packets(accel)) {
    for (int i = 0; i < count; ++i) occluded[i] = is_occluded(accel, *rays[i]);
    return;
  }
  RTCRay stream[stream_length];
  int traced[stream_length];
  RTCIntersectContext context = stream_context(coherence);
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
  if (accel.direct_shapes.enabled) return shapes_block_directly(accel, ray);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcOccluded1(accel.top, &context, &r);
  return r.tfar < 0;
}

}  // namespace radiant
