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
#include "accel/embree_callbacks.h"
#include "accel/embree_isa.h"
#include "accel/motion_geometry.h"
#include "scene/coordinate_range.h"
#include "scene/shape_bounds.h"

namespace radiant {

namespace {

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
  if (!mesh.motion_positions.empty())  // deforming while the shutter is open (never laid out flat)
    set_vertex_motion(geometry, mesh.motion_positions);
  else
    write_vertices(static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                               3 * sizeof(float), positions.size())),
                   positions);
  auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), mesh.triangle_count()));
  std::copy(mesh.indices.begin(), mesh.indices.begin() + 3 * mesh.triangle_count(), indices);
  rtcSetGeometryUserData(geometry, &accel.mesh_filters[mesh_index]);
  if (mesh.material >= 0 && accel.scene->materials[mesh.material].alpha_mode == AlphaMode::mask) {
    rtcSetGeometryIntersectFilterFunction(geometry, alpha_mask_filter);
    rtcSetGeometryOccludedFilterFunction(geometry, alpha_mask_filter);
  }
  rtcCommitGeometry(geometry);
  return geometry;
}

// The flags every scene of `accel` takes (`extra` besides): Embree calls a context's filter only
// in scenes that allow it, and only scenes with single-sided meshes need it.
RTCSceneFlags scene_flags(const SceneAccel& accel, int extra = 0) {
  int flags = RTC_SCENE_FLAG_ROBUST | extra;
  if (accel.has_single_sided) flags |= RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION;
  return RTCSceneFlags(flags);
}

RTCScene build_mesh_scene(SceneAccel& accel, int mesh_index) {
  RTCScene scene = rtcNewScene(accel.device);
  rtcSetSceneFlags(scene, scene_flags(accel));
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
  if (!instance.motion.empty()) set_transform_motion(geometry, instance.motion);
  else set_instance_transform(geometry, instance.transform);
  rtcCommitGeometry(geometry);
  return geometry;
}

// How many instances place each mesh: a mesh placed once may sit flat on the top level.
std::vector<int> mesh_placements(const SceneDesc& scene) {
  std::vector<int> placements(scene.meshes.size(), 0);
  for (const InstanceDesc& instance : scene.instances) ++placements[instance.mesh];
  return placements;
}

// Whether instance i may sit flat on the top level: its mesh placed once, nothing of it moving
// while the shutter is open (Embree moves instances and vertex buffers, not placed copies), and
// every placed vertex an exact float (placed into `world_positions`).
bool lies_flat(const SceneDesc& scene, const std::vector<int>& placements, const InstanceDesc& instance,
               std::vector<vec3>& world_positions) {
  const MeshDesc& mesh = scene.meshes[instance.mesh];
  return placements[instance.mesh] == 1 && instance.motion.empty() && mesh.motion_positions.empty() &&
         place_exactly(mesh, instance.transform, world_positions);
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
    bool flat = lies_flat(scene, placements, instance, world_positions);
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
  for (const StrokeDesc& stroke : scene.strokes)
    for (vec3 p : stroke.positions) reach = std::max(reach, double(max_component(abs(stroke.center + p))));
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

// Each stroke as a geometry of its own on the top level.
void attach_strokes(SceneAccel& accel, const StrokeSizing& sizing) {
  const std::vector<StrokeDesc>& strokes = accel.scene->strokes;
  accel.first_stroke_geometry = unsigned(accel.scene->instances.size()) + 1;
  accel.stroke_max_radius.assign(strokes.size(), 0);
  for (size_t k = 0; k < strokes.size(); ++k) {
    RTCGeometry geometry = new_stroke_geometry(accel.device, strokes[k], sizing, accel.stroke_max_radius[k]);
    rtcAttachGeometryByID(accel.top, geometry, accel.first_stroke_geometry + unsigned(k));
    rtcReleaseGeometry(geometry);
  }
}

}  // namespace

std::unique_ptr<SceneAccel> build_scene_accel(const SceneDesc& scene, AccelLayout layout, const StrokeSizing& strokes) {
  auto accel = std::make_unique<SceneAccel>();
  accel->scene = &scene;
  accel->device = rtcNewDevice(embree_device_config().c_str());
  if (!accel->device) throw std::runtime_error("cannot create the Embree device");
  rtcSetDeviceErrorFunction(accel->device, record_device_error, &device_error());
  accel->mesh_filters.resize(scene.meshes.size());
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    int material = scene.meshes[m].material;
    bool single_sided = material >= 0 && !scene.materials[size_t(material)].double_sided;
    accel->mesh_filters[m] = {accel.get(), int(m), single_sided};
    accel->has_single_sided |= single_sided;
  }
  accel->top = rtcNewScene(accel->device);
  if (layout == AccelLayout::two_level) {
    // DYNAMIC keeps the per-geometry builders after a commit, so the next one reuses their BVHs.
    rtcSetSceneFlags(accel->top, scene_flags(*accel, RTC_SCENE_FLAG_DYNAMIC));
    rtcSetSceneBuildQuality(accel->top, RTC_BUILD_QUALITY_LOW);
  } else {
    rtcSetSceneFlags(accel->top, scene_flags(*accel));
  }
  attach_instances(*accel);
  set_traceable_range(*accel);
  attach_shapes(*accel);
  attach_strokes(*accel, strokes);
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
    bool flat = lies_flat(scene, placements, instance, world_positions);
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

}  // namespace radiant
