// The .scene format's classic Phong units (colors 0-255) converted to radiant's internal
// radiometric units; the derivation is in docs/scene-format.md, "Units".
#pragma once

#include <cmath>

#include "math/vec.h"

namespace radiant::scene_format {

// Point, spot and directional lights: the Whitted model divides by pi (a Lambertian BRDF), so
// kd = 1 facing I = 255 at distance 1 shows pi * (255/255) / pi = 1, the classic full white.
inline color3 light_intensity_from_scene(color3 intensity_0_255) { return intensity_0_255 * (pi / 255.0f); }

// Ambient light is added as ka * A with no pi, so only the 0-255 scale is removed.
inline color3 ambient_from_scene(color3 ambient_0_255) { return ambient_0_255 / 255.0f; }

// Emission and background are radiance seen directly: 255 shows as 1.
inline color3 radiance_from_scene(color3 color_0_255) { return color_0_255 / 255.0f; }

// A view plane of height `plane_height` at `distance` from the eye spans this vertical angle.
inline float vertical_fov_from_view_plane(float distance, float plane_height) {
  return 2.0f * std::atan((plane_height / 2.0f) / distance) * 180.0f / pi;
}

}  // namespace radiant::scene_format
