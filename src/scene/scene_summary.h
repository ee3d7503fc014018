// What `radiant info` reports about a loaded scene: counts, memory, bounds and warnings.
#pragma once

#include <string>
#include <vector>

#include "scene/scene_desc.h"

namespace radiant {

struct SceneSummary {
  size_t meshes = 0, instances = 0, triangles = 0, instanced_triangles = 0;
  size_t spheres = 0, planes = 0, cylinders = 0, tubes = 0;
  size_t line_segments = 0, points = 0;  // strokes: round linear curves and spheres
  size_t materials = 0, textures = 0, images = 0, texture_bytes = 0, geometry_bytes = 0;
  size_t ambient_lights = 0, directional_lights = 0, point_lights = 0, spot_lights = 0, emissive_materials = 0;
  size_t cameras = 0;
  vec3 bounds_lower, bounds_upper;  // finite geometry (infinite planes and tubes excluded)
  bool has_bounds = false;
  std::vector<std::string> warnings;  // the loader's, plus the analysis below
};

// Emitted radiance above this lights a scene: glTF's emissive factor alone stops at 1, so a
// brighter surface is a lamp (KHR_materials_emissive_strength, a .scene emitter), while a
// dimmer one is a glowing detail (a screen, a label) that cannot light a model by itself.
constexpr float lamp_radiance = 1.0f;
inline bool is_lamp(const MaterialDesc& m) { return max_component(m.emission) > lamp_radiance; }

// True when the file lights itself: a light, an environment, or an emissive material brighter
// than lamp_radiance. Files that do not get the built-in studio environment by default.
bool lights_itself(const SceneDesc& scene);

// Counts and bounds, plus warnings: no light at all, and the loader's own warnings (lights
// enclosed by geometry need an accelerator: accel/light_enclosure.h).
SceneSummary summarize_scene(const SceneDesc& scene);

}  // namespace radiant
