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

vec3 direction_from_uv(vec2 uv, float& sin_theta) {
  float phi = (uv.x - 0.5f) * 2 * pi, theta = uv.y * pi;
  sin_theta = std::sin(theta);
  return {sin_theta * std::sin(phi), std::cos(theta), -sin_theta * std::cos(phi)};
}

float map_pdf(const LightTable& lights, vec3 d) {
  float u = 0.5f + std::atan2(d.x, -d.z) / (2 * pi);
  float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / pi;
  float sin_theta = std::sin(v * pi);
  if (sin_theta <= 0) return 0;
  return continuous_2d_pdf(lights.environment_map.distribution, {u, v}) / (2 * pi * pi * sin_theta);
}

}  // namespace

float sample_environment(const LightTable& lights, vec3 normal, float u_choice, vec2 u, vec3& direction) {
  float p_map = map_probability(lights);
  if (u_choice < p_map) {
    float uv_pdf, sin_theta;
    vec2 uv = sample_continuous_2d(lights.environment_map.distribution, u, uv_pdf);
    direction = direction_from_uv(uv, sin_theta);
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

}  // namespace radiant
