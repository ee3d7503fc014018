#include "lights/environment_light.h"

#include <cmath>

#include "sampling/warp.h"

namespace radiant {

namespace {

// Probability of sampling the map rather than the uniform sphere.
float map_probability(const LightTable& lights) {
  if (lights.environment_map.width == 0 || lights.environment_map.distribution.marginal.empty()) return 0;
  return is_black(lights.environment_color) ? 1.0f : 0.5f;
}

float map_pdf(const LightTable& lights, vec3 d) {
  vec2 uv = environment_uv(to_environment(lights.environment_frame, d));
  float sin_theta = std::sin(uv.y * pi);
  if (sin_theta <= 0) return 0;
  return continuous_2d_pdf(lights.environment_map.distribution, uv) / (2 * pi * pi * sin_theta);
}

// The uniform part plus the map as `lookup` reads it, along unit world direction `d`.
template <color3 (*lookup)(const EnvironmentMap&, vec2)>
color3 environment_radiance(const LightTable& lights, vec3 d) {
  color3 radiance = lights.environment_color;
  const EnvironmentMap& map = lights.environment_map;
  if (map.width > 0)
    radiance += lookup(map, environment_uv(to_environment(lights.environment_frame, d))) * lights.environment_scale;
  return radiance;
}

}  // namespace

float sample_environment(const LightTable& lights, vec3 normal, float u_choice, vec2 u, vec3& direction) {
  float p_map = map_probability(lights);
  if (u_choice < p_map) {
    float uv_pdf, sin_theta;
    vec2 uv = sample_continuous_2d(lights.environment_map.distribution, u, uv_pdf);
    direction = from_environment(lights.environment_frame, environment_direction(uv, sin_theta));
    if (sin_theta <= 0) return 0;
  } else {
    direction = to_world(normal, sample_cosine_hemisphere(u));
  }
  return environment_pdf(lights, normal, direction);
}

float environment_pdf(const LightTable& lights, vec3 normal, vec3 direction) {
  float p_map = map_probability(lights);
  float pdf = (1 - p_map) * std::max(0.0f, dot(normal, direction)) * inv_pi;
  if (p_map > 0) pdf += p_map * map_pdf(lights, direction);
  return pdf;
}

color3 eval_environment(const LightTable& lights, vec3 d) { return environment_radiance<environment_texel>(lights, d); }

color3 eval_environment_backdrop(const LightTable& lights, vec3 d) {
  return environment_radiance<environment_backdrop>(lights, d);
}

}  // namespace radiant
