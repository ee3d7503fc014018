// Turning an Embree hit into a SurfaceHit: position with its error bound, normals, attributes.
#include <cmath>

#include "accel/analytic_shapes.h"
#include "accel/scene_accel.h"
#include "accel/triangle_point.h"

namespace radiant {

namespace {

template <class T>
T interpolate(const std::vector<T>& values, const uint32_t* tri, float b0, float b1, float b2) {
  return barycentric_mix(values[tri[0]], values[tri[1]], values[tri[2]], b0, b1, b2);
}
vec4 interpolate4(const std::vector<vec4>& v, const uint32_t* tri, float b0, float b1, float b2) {
  const vec4 &a = v[tri[0]], &b = v[tri[1]], &c = v[tri[2]];
  return {a.x * b0 + b.x * b1 + c.x * b2, a.y * b0 + b.y * b1 + c.y * b2, a.z * b0 + b.z * b1 + c.z * b2,
          a.w * b0 + b.w * b1 + c.w * b2};
}

// dP/du and dP/dv of the triangle (object space) from its edges and their texcoord differences.
void triangle_uv_derivatives(const MeshDesc& mesh, const uint32_t* tri, vec3 e1, vec3 e2, SurfaceHit& hit) {
  vec2 uv0 = mesh.texcoords0[tri[0]], d1 = mesh.texcoords0[tri[1]] - uv0, d2 = mesh.texcoords0[tri[2]] - uv0;
  float determinant = d1.x * d2.y - d1.y * d2.x;
  if (!(std::abs(determinant) > 1e-20f)) return;  // no uv area: no slope to follow
  float inverse = 1 / determinant;
  hit.dpdu = (e1 * d2.y - e2 * d1.y) * inverse;
  hit.dpdv = (e2 * d1.x - e1 * d2.x) * inverse;
}

// An instance's placement at one time: its own transform, or where it is at a ray's time while
// it moves (the transform Embree interpolated to find the hit).
struct Placement {
  mat4 moved_world, moved_object;
  const mat4* to_world;
  const mat4* to_object;
  bool identity;
  float orientation;
};
void place_at_time(const SceneAccel& accel, int index, float time, Placement& p) {
  const InstanceDesc& instance = accel.scene->instances[size_t(index)];
  if (instance.motion.empty()) {
    p.to_world = &instance.transform, p.to_object = &accel.instance_inverse[size_t(index)];
    p.identity = accel.instance_identity[size_t(index)], p.orientation = accel.instance_orientation[size_t(index)];
    return;
  }
  p.moved_world = transform_at_time(instance.motion, time);
  inverse_affine(p.moved_world, p.moved_object);
  p.to_world = &p.moved_world, p.to_object = &p.moved_object;
  p.identity = false, p.orientation = determinant3(p.moved_world) < 0 ? -1.0f : 1.0f;
}

void fill_triangle_hit(const SceneAccel& accel, const HitId& id, float time, SurfaceHit& hit) {
  const SceneDesc& scene = *accel.scene;
  const InstanceDesc& instance = scene.instances[id.instance];
  const MeshDesc& mesh = scene.meshes[instance.mesh];
  Placement placement;
  place_at_time(accel, id.instance, time, placement);
  const mat4& to_world = *placement.to_world;
  const mat4& to_object = *placement.to_object;
  const uint32_t* tri = &mesh.indices[size_t(id.primitive) * 3];
  float b1 = id.barycentric.x, b2 = id.barycentric.y, b0 = 1 - b1 - b2;
  vec3 p0 = mesh.positions[tri[0]], p1 = mesh.positions[tri[1]], p2 = mesh.positions[tri[2]];
  if (!mesh.motion_positions.empty()) {  // deforming while the shutter is open: where Embree met it
    p0 = position_at_time(mesh.motion_positions, tri[0], time);
    p1 = position_at_time(mesh.motion_positions, tri[1], time);
    p2 = position_at_time(mesh.motion_positions, tri[2], time);
  }
  vec3 e1 = p1 - p0, e2 = p2 - p0;
  TrianglePoint object = triangle_point(p0, e1, e2, b1, b2);
  bool identity = placement.identity;
  vec3 error = object.error;
  hit.position = object.point;
  if (!identity) {
    hit.position = transform_point(to_world, object.point);
    error = world_point_error(Mat4Entries{to_world}, object.point, object.error);
  }
  // Embree's own ray-plane arithmetic mixes all three coordinates, so a surface lying in a
  // coordinate plane (error 0 along its normal) still needs an offset: use the largest bound
  // on every axis.
  float largest = max_component(error);
  hit.position_error = {largest, largest, largest};

  // The front side is where the world-space winding is counter-clockwise (glTF). Untransformed,
  // that is Embree's own Ng, which it computes anyway and documents as pointing out of the
  // counter-clockwise side (the accel layout test checks it against the cross product below).
  // Otherwise: the inverse transpose of the object normal, flipped for mirroring transforms.
  // Both normals are set from the register: copying one field of `hit` to the other would read
  // back a vector just written as separate floats, which stalls store forwarding.
  vec3 geometric_normal =
      identity ? normalize(id.geometric_normal_raw)
               : normalize(transform_normal(to_object, cross(e1, e2))) * placement.orientation;
  hit.geometric_normal = geometric_normal;
  hit.shading_normal = geometric_normal;
  if (!mesh.normals.empty()) {
    vec3 n = interpolate(mesh.normals, tri, b0, b1, b2);
    n = normalize(identity ? n : transform_normal(to_object, n));
    if (usable_vertex_normal(n)) hit.shading_normal = on_side_of(n, geometric_normal);
  }
  if (!mesh.tangents.empty()) {
    vec4 t = interpolate4(mesh.tangents, tri, b0, b1, b2);
    vec3 world = identity ? vec3{t.x, t.y, t.z} : transform_vector(to_world, {t.x, t.y, t.z});
    hit.tangent = {world.x, world.y, world.z, mesh.tangents[tri[0]].w < 0 ? -1.0f : 1.0f};
  }
  if (!mesh.texcoords0.empty()) hit.attributes.uv[0] = interpolate(mesh.texcoords0, tri, b0, b1, b2);
  if (!mesh.texcoords1.empty()) hit.attributes.uv[1] = interpolate(mesh.texcoords1, tri, b0, b1, b2);
  if (!mesh.colors.empty()) hit.attributes.vertex_color = interpolate4(mesh.colors, tri, b0, b1, b2);
  hit.material = mesh.material;
  if (scene.materials[size_t(mesh.material)].bump_texture.valid()) {
    // Zero (no bump) without texcoords or where they have no area; never a previous hit's.
    hit.dpdu = hit.dpdv = {0, 0, 0};
    if (!mesh.texcoords0.empty()) triangle_uv_derivatives(mesh, tri, e1, e2, hit);
    if (!identity) hit.dpdu = transform_vector(to_world, hit.dpdu), hit.dpdv = transform_vector(to_world, hit.dpdv);
  }
}

void fill_shape_hit(const SceneAccel& accel, const Ray& ray, const HitId& id, SurfaceHit& hit) {
  const ShapeDesc& shape = accel.scene->shapes[id.shape];
  vec3 normal = normalize(id.geometric_normal_raw);
  refine_shape_point(shape, ray.origin + ray.direction * id.t, normal, hit.position, hit.position_error);
  hit.geometric_normal = normal;
  hit.shading_normal = normal;
  hit.attributes.uv[0] = hit.attributes.uv[1] = id.barycentric;
  hit.material = shape.material;
}

// Lines and points: the point along the ray, bounded by its rounding (render space is centred on
// the camera, so |p| covers the distance travelled) and a share of the radius for Embree's
// iterative curve intersection.
void fill_stroke_hit(const SceneAccel& accel, const Ray& ray, const HitId& id, SurfaceHit& hit) {
  const StrokeDesc& stroke = accel.scene->strokes[id.stroke];
  vec3 normal = normalize(id.geometric_normal_raw);
  if (!is_finite(normal) || length_squared(normal) < 0.5f) normal = -ray.direction * (1 / length(ray.direction));
  vec3 p = ray.origin + ray.direction * id.t;
  float radius = accel.stroke_max_radius[id.stroke];
  vec4 color = {1, 1, 1, 1};
  if (stroke.kind == StrokeKind::points) {
    if (!stroke.colors.empty()) color = stroke.colors[id.primitive];
  } else if (!stroke.colors.empty()) {
    uint32_t first = stroke.segments[id.primitive];
    float u = std::clamp(id.barycentric.x, 0.0f, 1.0f);
    const vec4 &a = stroke.colors[first], &b = stroke.colors[first + 1];
    color = {a.x + (b.x - a.x) * u, a.y + (b.y - a.y) * u, a.z + (b.z - a.z) * u, a.w + (b.w - a.w) * u};
  }
  float error = rounding_gamma(4) * max_component(abs(p)) + 1e-3f * radius;
  hit.position = p;
  hit.position_error = {error, error, error};
  hit.geometric_normal = normal;
  hit.shading_normal = normal;
  hit.attributes.vertex_color = color;
  hit.material = stroke.material;
}

}  // namespace

SurfaceHit make_surface_hit(const SceneAccel& accel, const Ray& ray, const HitId& id) {
  SurfaceHit hit;
  if (id.instance >= 0) fill_triangle_hit(accel, id, ray.time, hit);
  else if (id.stroke >= 0) fill_stroke_hit(accel, ray, id, hit);
  else fill_shape_hit(accel, ray, id, hit);
  hit.front_face = arrives_on_front(ray.direction, hit.geometric_normal);
  hit.time = ray.time;
  return hit;
}

}  // namespace radiant
