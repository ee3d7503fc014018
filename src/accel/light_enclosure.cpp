#include "accel/light_enclosure.h"

#include <algorithm>

#include "accel/scene_accel.h"

namespace radiant {

namespace {

// A light is enclosed when rays in all six axis directions hit the back of some surface.
bool light_is_enclosed(const SceneAccel& accel, vec3 position) {
  const vec3 directions[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (vec3 d : directions) {
    Ray ray{position, normalize(d + vec3{0.0123f, 0.0071f, 0.0037f})};
    HitId id = intersect_nearest(accel, ray);
    if (!id.valid()) return false;
    if (make_surface_hit(accel, ray, id).front_face) return false;
  }
  return true;
}

}  // namespace

std::vector<std::string> enclosed_light_warnings(const SceneDesc& scene) {
  std::vector<std::string> warnings;
  bool point_lights = std::any_of(scene.lights.begin(), scene.lights.end(), [](const LightDesc& l) {
    return l.kind == LightKind::point || l.kind == LightKind::spot;
  });
  if (!point_lights || (scene.instances.empty() && scene.shapes.empty() && scene.strokes.empty())) return warnings;
  auto accel = build_scene_accel(scene);  // an accelerator only to test them
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const LightDesc& l = scene.lights[i];
    if ((l.kind == LightKind::point || l.kind == LightKind::spot) && light_is_enclosed(*accel, l.position))
      warnings.push_back("light " + (l.name.empty() ? "#" + std::to_string(i) : "'" + l.name + "'") +
                         " is inside closed geometry: it lights only the inside");
  }
  return warnings;
}

}  // namespace radiant
