#include "lights/delta_light.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace radiant {

namespace {

float spot_falloff(const LightDesc& light, vec3 light_to_point) {
  float cos_angle = dot(light.direction, light_to_point);
  if (light.use_cone) {
    // The glTF KHR_lights_punctual smooth falloff between the outer and inner cone.
    float cos_outer = std::cos(light.outer_cone), cos_inner = std::cos(light.inner_cone);
    float scale = 1.0f / std::max(0.001f, cos_inner - cos_outer);
    float t = std::clamp((cos_angle - cos_outer) * scale, 0.0f, 1.0f);
    return t * t;
  }
  // The classic narrow beam: cos^exponent in front of the light, nothing behind it.
  return cos_angle > 0 ? std::pow(cos_angle, light.spot_exponent) : 0.0f;
}

}  // namespace

bool sample_any_delta_light(const LightDesc& light, vec3 point, DeltaLightSample& sample) {
  switch (light.kind) {
    case LightKind::ambient: return false;
    case LightKind::directional:
      sample.direction = -light.direction;
      sample.distance = std::numeric_limits<float>::infinity();
      sample.irradiance = light.intensity;
      return true;
    case LightKind::point:
    case LightKind::spot: {
      float attenuation;
      if (!reach_point_light(light, point, sample, attenuation)) return false;
      float d = sample.distance;
      float falloff = 1;
      if (light.kind == LightKind::spot) falloff = spot_falloff(light, -sample.direction);
      if (light.range > 0) {
        float r = d / light.range;
        falloff *= std::clamp(1 - r * r * r * r, 0.0f, 1.0f);
      }
      if (falloff <= 0) return false;
      sample.irradiance = light.intensity * (falloff / attenuation);
      return true;
    }
  }
  return false;
}

}  // namespace radiant
