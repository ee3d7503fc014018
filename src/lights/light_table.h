// Every light of a scene in the form the integrators sample: delta lights, emissive triangles
// and spheres as area lights, and the environment, chosen in proportion to their power or, with
// many lights, by a light BVH (lights/light_selection.h chooses).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "lights/environment_map.h"
#include "lights/light_bvh.h"
#include "math/vec.h"
#include "memory/memory_budget.h"
#include "sampling/distribution.h"
#include "scene/scene_desc.h"

namespace radiant {

enum class AreaLightShape { triangle, sphere };

struct AreaLight {
  AreaLightShape shape = AreaLightShape::triangle;
  vec3 p0, p1, p2;          // world-space triangle
  vec3 center;              // sphere
  float radius = 0;
  vec3 normal;              // triangle front normal (unit)
  float area = 0;
  int material = -1;
  // The luminance of its mean emitted radiance (lights/emission_estimate.h): what its selection
  // weight and its light-BVH bounds go by.
  float radiance = 0;
  bool two_sided = false;
  int instance = -1, shape_index = -1;
  uint32_t primitive = 0;
};

// The environment a render asks for: a uniform colour, a map file or the built-in studio (or
// both a colour and a map), scaled, and turned with the world's up (lights/environment_map.h).
struct EnvironmentSpec {
  color3 color;
  std::string map_path;
  bool studio = false;
  float map_scale = 1;       // the map's radiance factor (the scene's, times the intensity)
  EnvironmentFrame frame;
  bool has_map() const { return studio || !map_path.empty(); }
  bool exists() const { return has_map() || !is_black(color); }
};

struct LightTable {
  std::vector<int> delta_lights;        // indices of point, spot and directional lights
  std::vector<AreaLight> area_lights;
  color3 environment_color;             // uniform part of the environment
  EnvironmentMap environment_map;       // width 0 when there is none
  float environment_scale = 1;          // the map's radiance factor
  EnvironmentFrame environment_frame;    // the map's axes in world space
  vec3 scene_center;                    // bounding sphere, for the power of infinite lights
  float scene_radius = 1;

  // Selection among [delta lights..., area lights..., environment] by power.
  Distribution1D selection;
  // How a light is chosen (power or bvh, never automatic). With `bvh`, the lights at infinity
  // (directional lights, the environment) and the tree as one entry are chosen by power, then a
  // light of the tree by its importance at the shading point.
  LightSampler sampler = LightSampler::power;
  LightBvh bvh;                          // point and spot lights, emissive triangles and spheres
  Distribution1D infinite_selection;     // over [infinite_lights..., the tree]
  std::vector<int> infinite_lights;      // their slots in [delta lights..., area lights..., environment]
  MemoryCharge bvh_memory;               // the tree, held against the budget
  std::vector<int> instance_light_base;  // first area light of each instance's triangles, or -1
  std::vector<int> shape_light;          // area light of each analytic shape, or -1
  MemoryCharge area_light_memory;        // held against the budget
  bool has_environment() const { return !is_black(environment_color) || environment_map.width > 0; }
  size_t environment_slot() const { return delta_lights.size() + area_lights.size(); }
};

// Lights with a position from which `automatic` chooses the BVH: with fewer, power sampling's
// choice costs one table lookup, and a scene with one light pays nothing for the tree.
constexpr size_t light_bvh_min_lights = 8;

// Builds the table. `environment` is the resolved environment (scene, then --env and its
// flags). `budget` (when given) is charged for the area lights, the light BVH and the
// environment map (by the size its header declares) before they are built.
// `sampler` is how the path tracer will choose lights (`automatic` is resolved here; Whitted,
// without area lights, gets power: it chooses none). Throws std::runtime_error when the map
// cannot be read, MemoryLimitError when the budget refuses.
// `emission_textures`: whether the render reads emission textures (the textures effect), so
// that emissive triangles are weighed by what they will emit (lights/emission_estimate.h).
LightTable make_light_table(const SceneDesc& scene, const EnvironmentSpec& environment, bool use_area_lights,
                            MemoryBudget* budget = nullptr, LightSampler sampler = LightSampler::automatic,
                            bool emission_textures = true);
// The same with a uniform environment and an optional map file, as most tests want.
inline LightTable make_light_table(const SceneDesc& scene, color3 environment_color,
                                   const std::string& environment_map_path, bool use_area_lights,
                                   MemoryBudget* budget = nullptr, LightSampler sampler = LightSampler::automatic,
                                   bool emission_textures = true) {
  EnvironmentSpec environment;
  environment.color = environment_color;
  environment.map_path = environment_map_path;
  return make_light_table(scene, environment, use_area_lights, budget, sampler, emission_textures);
}

}  // namespace radiant
