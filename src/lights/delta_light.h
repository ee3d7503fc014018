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

// The direction and distance from `point` to a point or spot light and its attenuation there
// (the inverse-square law's polynomial); false at the light or where the attenuation is not
// positive.
[[gnu::always_inline]] inline bool reach_point_light(const LightDesc& light, vec3 point, DeltaLightSample& sample,
                                                     float& attenuation) {
  vec3 to_light = light.position - point;
  float d = length(to_light);
  if (!(d > 0)) return false;
  sample.direction = to_light * (1 / d);
  sample.distance = d;
  sample.position = light.position;
  attenuation = light.kc + light.kl * d + light.kq * d * d;
  return attenuation > 0;
}

// sample_delta_light for every kind of light.
bool sample_any_delta_light(const LightDesc& light, vec3 point, DeltaLightSample& sample);

// False when the point receives nothing (outside a spot cone, beyond range, at the light). A point
// light without range, the common case, is sampled inline: out of line, the call's argument
// passing stalled on store forwarding at every path vertex.
[[gnu::always_inline]] inline bool sample_delta_light(const LightDesc& light, vec3 point, DeltaLightSample& sample) {
  if (light.kind != LightKind::point || light.range > 0) return sample_any_delta_light(light, point, sample);
  float attenuation;
  if (!reach_point_light(light, point, sample, attenuation)) return false;
  sample.irradiance = light.intensity * (1.0f / attenuation);  // sample_any_delta_light's, with falloff 1
  return true;
}

}  // namespace radiant
