#include "lights/delta_light.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace radiant {

namespace {

float spot_falloff(const LightDesc& light, vec3 light_to_point) {
  float cos_angle = dot(light.direction, light_to_point);
  if (light.use_cone) return smooth_cone_falloff(cos_angle, spot_cone(light));
  return classic_spot_falloff(cos_angle, light.spot_exponent);
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
      if (light.range > 0) falloff *= range_window(d, light.range);
      if (falloff <= 0) return false;
      sample.irradiance = light.intensity * (falloff / attenuation);
      return true;
    }
  }
  return false;
}

}  // namespace radiant
