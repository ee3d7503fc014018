// What `radiant info` reports about a loaded scene: counts, memory, bounds and warnings.
#pragma once

#include <string>
#include <vector>

#include "scene/scene_desc.h"

namespace radiant {

struct SceneSummary {
  size_t meshes = 0, instances = 0, triangles = 0, instanced_triangles = 0;
  size_t spheres = 0, planes = 0, cylinders = 0, tubes = 0;
  size_t materials = 0, textures = 0, images = 0, texture_bytes = 0, geometry_bytes = 0;
  size_t ambient_lights = 0, directional_lights = 0, point_lights = 0, spot_lights = 0, emissive_materials = 0;
  size_t cameras = 0;
  vec3 bounds_lower, bounds_upper;  // finite geometry (infinite planes and tubes excluded)
  bool has_bounds = false;
  std::vector<std::string> warnings;  // the loader's, plus the analysis below
};

// True when something in the file emits light: a light, an emissive material or an environment.
bool has_light_sources(const SceneDesc& scene);

// Counts and bounds, plus warnings: no light at all, lights enclosed by geometry (checked by
// casting rays from each point or spot light), and the loader's own warnings.
SceneSummary summarize_scene(const SceneDesc& scene);

}  // namespace radiant
