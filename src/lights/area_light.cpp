#include "lights/area_light.h"

#include <cmath>

#include "sampling/warp.h"

namespace radiant {

namespace {

// Cone sampling of a sphere seen from outside (pbrt 6.2.4); uniform area sampling from inside.
bool sample_sphere(const AreaLight& light, vec3 from, vec2 u, AreaLightSample& s) {
  vec3 to_center = light.center - from;
  float d2 = length_squared(to_center);
  float r2 = light.radius * light.radius;
  if (d2 <= r2 * 1.0001f) {
    vec3 n = sample_uniform_sphere(u);
    s.position = light.center + n * light.radius;
    s.normal = n;
    vec3 d = s.position - from;
    s.distance = length(d);
    if (!(s.distance > 0)) return false;
    s.direction = d / s.distance;
    float cos_light = std::abs(dot(n, s.direction));
    if (cos_light <= 0) return false;
    s.pdf = s.distance * s.distance / (light.area * cos_light);
    return true;
  }
  float d = std::sqrt(d2);
  float sin2_max = r2 / d2;
  float cos_max = std::sqrt(std::max(0.0f, 1 - sin2_max));
  vec3 axis = to_center / d;
  vec3 local = sample_uniform_cone(u, cos_max);
  s.direction = to_world(axis, local);
  // Distance to the near intersection with the sphere along the sampled direction.
  float b = dot(s.direction, to_center);
  float c = d2 - r2;
  float discriminant = std::max(0.0f, b * b - c);
  s.distance = b - std::sqrt(discriminant);
  s.position = from + s.direction * s.distance;
  s.normal = normalize(s.position - light.center);
  s.pdf = 1 / (2 * pi * (1 - cos_max));
  return std::isfinite(s.pdf) && s.pdf > 0;
}

}  // namespace

bool sample_area_light(const AreaLight& light, vec3 from, vec2 u, AreaLightSample& s) {
  if (light.shape == AreaLightShape::sphere) return sample_sphere(light, from, u, s);
  vec2 b = sample_uniform_triangle(u);
  s.barycentric = b;
  s.position = light.p0 * (1 - b.x - b.y) + light.p1 * b.x + light.p2 * b.y;
  s.normal = light.normal;
  vec3 d = s.position - from;
  s.distance = length(d);
  if (!(s.distance > 0) || light.area <= 0) return false;
  s.direction = d / s.distance;
  float cos_light = std::abs(dot(s.normal, s.direction));
  if (cos_light <= 1e-7f) return false;
  s.pdf = s.distance * s.distance / (light.area * cos_light);
  return std::isfinite(s.pdf);
}

float area_light_pdf(const AreaLight& light, vec3 from, vec3 on_light, vec3 light_normal) {
  if (light.shape == AreaLightShape::sphere) {
    float d2 = length_squared(light.center - from);
    float r2 = light.radius * light.radius;
    if (d2 > r2 * 1.0001f) {
      float cos_max = std::sqrt(std::max(0.0f, 1 - r2 / d2));
      return 1 / (2 * pi * (1 - cos_max));
    }
  }
  vec3 d = on_light - from;
  float dist2 = length_squared(d);
  float cos_light = std::abs(dot(light_normal, d)) / std::sqrt(dist2);
  if (cos_light <= 1e-7f || light.area <= 0) return 0;
  return dist2 / (light.area * cos_light);
}

}  // namespace radiant
