#include "render/render_space.h"

#include <cmath>

#include "render/camera.h"
#include "scene/scene_bounds.h"

namespace radiant {

WorldPlacement record_world_placement(const SceneDesc& world) {
  WorldPlacement placement;
  placement.cameras = world.cameras;
  placement.has_framing_box = framing_box(world, placement.framing_lower, placement.framing_upper);
  placement.instance_translations.reserve(world.instances.size());
  for (const InstanceDesc& instance : world.instances) {
    const mat4& m = instance.transform;
    placement.instance_translations.push_back({m.m[0][3], m.m[1][3], m.m[2][3]});
    std::vector<vec3>& steps = placement.instance_motion_translations.emplace_back();
    for (const mat4& step : instance.motion) steps.push_back({step.m[0][3], step.m[1][3], step.m[2][3]});
  }
  placement.shape_centers.reserve(world.shapes.size());
  for (const ShapeDesc& shape : world.shapes) placement.shape_centers.push_back(shape.center);
  for (const StrokeDesc& stroke : world.strokes) placement.stroke_centers.push_back(stroke.center);
  placement.light_positions.reserve(world.lights.size());
  for (const LightDesc& light : world.lights) placement.light_positions.push_back(light.position);
  placement.has_bounds = scene_bounds(world, placement.lower, placement.upper);
  return placement;
}

dvec3 choose_render_origin(const WorldPlacement& world, vec3 camera_position) {
  dvec3 camera = to_double(camera_position);
  double size = 0;
  if (world.has_bounds) {
    dvec3 lower = to_double(world.lower), upper = to_double(world.upper);
    dvec3 diagonal = upper - lower, to_center = camera - (lower + upper) * 0.5;
    size = 2 * (std::sqrt(dot(diagonal, diagonal)) + std::sqrt(dot(to_center, to_center)));
  }
  // Nothing finite to measure (only planes and tubes): centre on the camera itself.
  if (!(size > 0)) return camera;
  double spacing = std::exp2(std::ceil(std::log2(size)));
  auto snap = [&](double v) { return std::round(v / spacing) * spacing; };
  return {snap(camera.x), snap(camera.y), snap(camera.z)};
}

void place_at_render_origin(SceneDesc& scene, const WorldPlacement& world, dvec3 origin) {
  for (size_t i = 0; i < scene.cameras.size(); ++i)
    scene.cameras[i].position = to_render_space(world.cameras[i].position, origin);
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    mat4& transform = scene.instances[i].transform;
    vec3 moved = to_render_space(world.instance_translations[i], origin);
    transform.m[0][3] = moved.x, transform.m[1][3] = moved.y, transform.m[2][3] = moved.z;
    std::vector<mat4>& motion = scene.instances[i].motion;
    for (size_t k = 0; k < motion.size(); ++k) {
      vec3 step = to_render_space(world.instance_motion_translations[i][k], origin);
      motion[k].m[0][3] = step.x, motion[k].m[1][3] = step.y, motion[k].m[2][3] = step.z;
    }
  }
  for (size_t i = 0; i < scene.shapes.size(); ++i) scene.shapes[i].center = to_render_space(world.shape_centers[i], origin);
  for (size_t i = 0; i < scene.strokes.size(); ++i)
    scene.strokes[i].center = to_render_space(world.stroke_centers[i], origin);
  for (size_t i = 0; i < scene.lights.size(); ++i)
    scene.lights[i].position = to_render_space(world.light_positions[i], origin);
}

}  // namespace radiant
