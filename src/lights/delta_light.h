// Point, spot and directional lights: light arriving at a point from a single direction.
#pragma once

#include "math/vec.h"
#include "scene/scene_desc.h"

namespace radiant {

struct DeltaLightSample {
  vec3 direction;     // unit, from the shaded point towards the light
  float distance = 0; // to the light; infinity for directional lights
  vec3 position;      // light position (unused for directional lights)
  color3 irradiance;  // at normal incidence: intensity * falloff / attenuation (W/m^2)
};

// False when the point receives nothing (outside a spot cone, beyond range, at the light).
bool sample_delta_light(const LightDesc& light, vec3 point, DeltaLightSample& sample);

}  // namespace radiant
