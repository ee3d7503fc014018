#include "scene/scene_summary.h"

#include <algorithm>
#include <limits>

#include "scene/scene_bounds.h"

namespace radiant {

namespace {

void count_geometry(const SceneDesc& scene, SceneSummary& s) {
  s.meshes = scene.meshes.size();
  s.instances = scene.instances.size();
  for (const MeshDesc& m : scene.meshes) {
    s.triangles += m.triangle_count();
    s.geometry_bytes += m.positions.size() * sizeof(vec3) + m.normals.size() * sizeof(vec3) +
                        m.tangents.size() * sizeof(vec4) + (m.texcoords0.size() + m.texcoords1.size()) * sizeof(vec2) +
                        m.colors.size() * sizeof(vec4) + m.indices.size() * sizeof(uint32_t);
  }
  for (const InstanceDesc& i : scene.instances) s.instanced_triangles += scene.meshes[i.mesh].triangle_count();
  for (const ShapeDesc& shape : scene.shapes) {
    switch (shape.kind) {
      case ShapeKind::sphere: s.spheres++; break;
      case ShapeKind::plane: s.planes++; break;
      case ShapeKind::cylinder: s.cylinders++; break;
      case ShapeKind::tube: s.tubes++; break;
    }
  }
  for (const StrokeDesc& stroke : scene.strokes) {
    (stroke.kind == StrokeKind::lines ? s.line_segments : s.points) += stroke.primitive_count();
    s.geometry_bytes += stroke.positions.size() * sizeof(vec3) + stroke.colors.size() * sizeof(vec4) +
                        stroke.segments.size() * sizeof(uint32_t);
  }
}

}  // namespace

bool lights_itself(const SceneDesc& scene) {
  if (!scene.lights.empty() || !is_black(scene.environment.color) || !scene.environment.map_path.empty()) return true;
  for (const MaterialDesc& m : scene.materials)
    if (is_lamp(m)) return true;
  return false;
}

SceneSummary summarize_scene(const SceneDesc& scene) {
  SceneSummary s;
  count_geometry(scene, s);
  s.has_bounds = scene_bounds(scene, s.bounds_lower, s.bounds_upper);
  s.materials = scene.materials.size();
  s.textures = scene.textures.size();
  s.images = scene.images.size();
  for (const ImageDesc& image : scene.images) s.texture_bytes += image.texels8.size() + image.texels_float.size() * sizeof(float);
  for (const MaterialDesc& m : scene.materials) s.emissive_materials += !is_black(m.emission);
  s.cameras = scene.cameras.size();
  for (const LightDesc& l : scene.lights) {
    switch (l.kind) {
      case LightKind::ambient: s.ambient_lights++; break;
      case LightKind::directional: s.directional_lights++; break;
      case LightKind::point: s.point_lights++; break;
      case LightKind::spot: s.spot_lights++; break;
    }
  }
  s.warnings = scene.warnings;
  if (scene.degenerate_triangles_dropped > 0)
    s.warnings.push_back(std::to_string(scene.degenerate_triangles_dropped) + " degenerate triangle(s) dropped");
  if (!lights_itself(scene))
    s.warnings.push_back(std::string(s.emissive_materials ? "no lights or environment, and no emissive material bright enough to light it"
                                                          : "no lights, emissive materials or environment") +
                         ": rendered under the built-in studio environment unless --env is given");
  return s;
}

}  // namespace radiant
