#include "support/scene_builders.h"

namespace radiant::test {

int add_material(SceneDesc& scene, const MaterialDesc& material) {
  scene.materials.push_back(material);
  return int(scene.materials.size()) - 1;
}

int add_diffuse(SceneDesc& scene, color3 kd) {
  MaterialDesc m;
  m.kd = kd;
  return add_material(scene, m);
}

void add_sphere(SceneDesc& scene, vec3 center, float radius, int material) {
  ShapeDesc s;
  s.kind = ShapeKind::sphere;
  s.center = center;
  s.radius = radius;
  s.material = material;
  scene.shapes.push_back(s);
}

void add_plane(SceneDesc& scene, vec3 point, vec3 normal, int material) {
  ShapeDesc s;
  s.kind = ShapeKind::plane;
  s.center = point;
  s.axis = normalize(normal);
  s.material = material;
  scene.shapes.push_back(s);
}

void add_quad(SceneDesc& scene, vec3 a, vec3 b, vec3 c, vec3 d, int material) {
  MeshDesc mesh;
  mesh.material = material;
  mesh.positions = {a, b, c, d};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  scene.meshes.push_back(mesh);
  InstanceDesc instance;
  instance.mesh = int(scene.meshes.size()) - 1;
  scene.instances.push_back(instance);
}

LightDesc point_light(vec3 position, color3 intensity, float kc, float kl, float kq) {
  LightDesc l;
  l.kind = LightKind::point;
  l.position = position;
  l.intensity = intensity;
  l.kc = kc, l.kl = kl, l.kq = kq;
  return l;
}

CameraDesc ortho_camera(vec3 position, vec3 forward, vec3 up, float height) {
  CameraDesc c;
  c.projection = Projection::orthographic;
  c.position = position;
  c.forward = normalize(forward);
  c.up = normalize(up);
  c.ortho_height = height;
  return c;
}

CameraDesc perspective_camera(vec3 position, vec3 forward, vec3 up, float vfov_degrees) {
  CameraDesc c;
  c.position = position;
  c.forward = normalize(forward);
  c.up = normalize(up);
  c.vertical_fov_degrees = vfov_degrees;
  return c;
}

RenderResult render_scene(const SceneDesc& scene, const RenderOptions& options) {
  PreparedScene prepared = prepare_scene(scene, options);
  return render_prepared(prepared, options);
}

}  // namespace radiant::test
