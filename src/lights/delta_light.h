// Point, spot and directional lights: light arriving at a point from a single direction.
#pragma once

#include <algorithm>
#include <cmath>

#include "math/vec.h"
#include "scene/scene_desc.h"

namespace radiant {

struct DeltaLightSample {
  vec3 direction;     // unit, from the shaded point towards the light
  float distance = 0; // to the light; infinity for directional lights
  vec3 position;      // light position (unused for directional lights)
  color3 irradiance;  // at normal incidence: intensity * falloff / attenuation (W/m^2)
};

// The formulas below are written over a lane (math/lane.h): one path's light sample and the
// batch's SIMD lanes (integrators/surface_lane_lights.h) call the same code.

// The inverse-square law's polynomial at distance `d` from a point or spot light.
[[gnu::always_inline]] inline float point_light_attenuation(float kc, float kl, float kq, float d) {
  return kc + kl * d + kq * d * d;
}
// A glTF spot's cone (KHR_lights_punctual): the cosine of its outer angle, and the scale that
// takes the cosine from there to the inner angle's across [0, 1].
struct SpotCone {
  float cos_outer, scale;
};
inline SpotCone spot_cone(const LightDesc& light) {
  float cos_outer = std::cos(light.outer_cone), cos_inner = std::cos(light.inner_cone);
  return {cos_outer, 1.0f / std::max(0.001f, cos_inner - cos_outer)};
}
// The glTF spot's smooth falloff between the outer and inner cone at `cos_angle` off its axis.
[[gnu::always_inline]] inline float smooth_cone_falloff(float cos_angle, SpotCone cone) {
  float t = std::clamp((cos_angle - cone.cos_outer) * cone.scale, 0.0f, 1.0f);
  return t * t;
}
// The classic narrow beam's falloff: cos^exponent in front of the light, nothing behind it.
inline float classic_spot_falloff(float cos_angle, float exponent) {
  return cos_angle > 0 ? std::pow(cos_angle, exponent) : 0.0f;
}
// The glTF range's window at distance `d`: 1 at the light, 0 from `range` on.
[[gnu::always_inline]] inline float range_window(float d, float range) {
  float r = d / range;
  return std::clamp(1 - r * r * r * r, 0.0f, 1.0f);
}

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
  attenuation = point_light_attenuation(light.kc, light.kl, light.kq, d);
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
