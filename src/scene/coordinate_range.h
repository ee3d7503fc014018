// The range of coordinates radiant supports, and the bound every ray handed to Embree keeps.
//
// Embree rejects (with an assertion that aborts the process) any ray whose origin or direction
// has a component beyond about 1.8e18 (its FLT_LARGE), and it applies the same test again to a
// ray transformed into an instance's object space. radiant therefore:
//  - refuses at load any position or size beyond max_scene_coordinate (docs/stability.md);
//  - renders in a space whose origin sits near the camera (render/render_space.h), so the
//    numbers Embree sees are the scene's extent, not its distance from the world origin;
//  - bounds every ray it traces by max_traced_coordinate divided by the largest shrink of any
//    instance, so that the ray stays valid in every object space (accel/scene_accel.h).
#pragma once

namespace radiant {

// Positions (vertices after placement, shape centres, lights, cameras) and sizes (radii,
// heights, orthographic view heights) must lie within this magnitude. Float spacing there is
// about 1e8 units: nothing a scene needs, far inside Embree's range.
constexpr double max_scene_coordinate = 1e15;
constexpr const char* max_scene_coordinate_text = "1e15";  // the same, for messages

// No traced ray, in render space or in any instance's object space, has an origin or direction
// component beyond this: a tenth of Embree's limit, leaving room for its own arithmetic.
constexpr double max_traced_coordinate = 1e17;

}  // namespace radiant
