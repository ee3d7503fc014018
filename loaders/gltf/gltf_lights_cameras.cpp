#include "gltf/gltf_lights_cameras.h"

#include <cmath>

namespace radiant {

// The node's -Z axis in world space: where lights shine and cameras look.
static vec3 world_forward(const GltfContext& context, const mat4& world, const std::string& where) {
  vec3 forward = transform_vector(world, {0, 0, -1});
  if (!(length(forward) > 0) || !is_finite(forward)) context.fail(where, "degenerate node transform");
  return normalize(forward);
}

void add_light(GltfContext& context, int index, const mat4& world, const std::string& where) {
  check_index(context, index, context.model.lights.size(), where, "light");
  const tinygltf::Light& source = context.model.lights[index];
  std::string at = "extensions.KHR_lights_punctual." + element("lights", size_t(index));
  LightDesc light;
  light.name = source.name.empty() ? element("lights", size_t(index)) : source.name;
  color3 color = {1, 1, 1};
  if (source.color.size() >= 3)
    for (int c = 0; c < 3; ++c) color[c] = non_negative_float(context, source.color[size_t(c)], at + ".color");
  // Radiometric 1:1 (docs/gltf-obj.md): cd -> W/sr, lux -> W/m^2.
  light.intensity = color * non_negative_float(context, source.intensity, at + ".intensity");
  light.position = transform_point(world, {0, 0, 0});
  light.direction = world_forward(context, world, where);
  light.kc = 0, light.kl = 0, light.kq = 1;
  light.range = float(source.range);
  if (source.type == "directional") {
    light.kind = LightKind::directional;
  } else if (source.type == "point") {
    light.kind = LightKind::point;
  } else if (source.type == "spot") {
    light.kind = LightKind::spot;
    light.use_cone = true;
    light.inner_cone = float(source.spot.innerConeAngle);
    light.outer_cone = float(source.spot.outerConeAngle);
  } else {
    context.fail(element("lights", size_t(index)) + ".type", "unknown light type '" + source.type + "'");
  }
  context.scene.lights.push_back(light);
}

void add_camera(GltfContext& context, int index, const mat4& world, const std::string& node_name,
                const std::string& where) {
  check_index(context, index, context.model.cameras.size(), where, "camera");
  const tinygltf::Camera& source = context.model.cameras[index];
  std::string at = element("cameras", size_t(index));
  CameraDesc camera;
  camera.name = !source.name.empty() ? source.name : node_name;
  camera.position = transform_point(world, {0, 0, 0});
  camera.forward = world_forward(context, world, where);
  // Scale and shear are dropped: up is made orthogonal to forward and unit length.
  vec3 up = transform_vector(world, {0, 1, 0});
  up = up - camera.forward * dot(up, camera.forward);
  if (!(length(up) > 0)) context.fail(where, "degenerate camera transform");
  camera.up = normalize(up);
  if (source.type == "orthographic") {
    camera.projection = Projection::orthographic;
    if (!(source.orthographic.ymag > 0) || !(source.orthographic.xmag > 0))
      context.fail(at + ".orthographic", "xmag and ymag must be positive");
    camera.ortho_height = float(source.orthographic.ymag * 2);
    camera.aspect = float(source.orthographic.xmag / source.orthographic.ymag);
  } else {
    const double yfov = source.perspective.yfov;
    if (!(yfov > 0 && yfov < pi)) context.fail(at + ".perspective.yfov", "must be in (0, pi)");
    camera.vertical_fov_degrees = float(yfov * 180 / pi);
    camera.aspect = source.perspective.aspectRatio > 0 ? float(source.perspective.aspectRatio) : 0;
  }
  context.scene.cameras.push_back(camera);
}

}  // namespace radiant
