// Render space: the world translated so that the camera sits near the origin, as pbrt-v4
// renders by default ("cameraworld"). Float coordinates then measure the scene's extent and the
// camera's distance to it, not the distance from the world origin, so a scene far from the
// origin renders as it would at the origin (docs/stability.md).
//
// Loaders produce world space; prepare_scene (render/render.h) records the world placement once
// and writes every world-space position minus the render origin, computed in double. Placing a
// scene is therefore a pure function of the file and the origin, and the origin a pure function
// of the view: a batch of views gives the same bytes as separate renders.
#pragma once

#include <vector>

#include "math/dvec3.h"
#include "scene/scene_desc.h"

namespace radiant {

// World-space values of everything the render origin moves, as loaded.
struct WorldPlacement {
  std::vector<CameraDesc> cameras;
  bool has_framing_box = false;  // what a framing camera frames (render/camera.h framing_box)
  vec3 framing_lower, framing_upper;
  std::vector<vec3> instance_translations;  // placing moves only an instance's translation column
  std::vector<std::vector<vec3>> instance_motion_translations;  // and those of its motion steps
  std::vector<vec3> shape_centers;
  std::vector<vec3> stroke_centers;
  std::vector<vec3> light_positions;
  bool has_bounds = false;  // finite geometry exists; then `lower`/`upper` bound it
  vec3 lower, upper;
};

WorldPlacement record_world_placement(const SceneDesc& world);

// The render origin for a camera at `camera_position` (world space): the camera position rounded
// to a grid whose spacing is a power of two at least twice the scene's size plus the camera's
// distance to it. The camera and the scene then lie within a few scene sizes of the origin
// (precision as at the world origin), a scene near the world origin keeps origin 0 (renders
// unchanged), and nearby views share one origin, so a batch rebuilds its accelerator only when
// the camera moves far.
dvec3 choose_render_origin(const WorldPlacement& world, vec3 camera_position);

// Writes the world placement, translated by -origin, into `scene` (same layout as the world
// scene it was recorded from).
void place_at_render_origin(SceneDesc& scene, const WorldPlacement& world, dvec3 origin);

// A world-space point in render space: rounded once, after an exact double subtraction.
inline vec3 to_render_space(vec3 world_point, dvec3 origin) { return to_float(to_double(world_point) - origin); }

}  // namespace radiant
