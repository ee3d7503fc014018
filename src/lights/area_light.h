// Sampling points on emissive triangles and spheres as seen from a shaded point.
#pragma once

#include "lights/light_table.h"

namespace radiant {

struct AreaLightSample {
  vec3 position;
  vec3 normal;         // at the sampled point, facing outward (front side)
  vec3 direction;      // unit, from the shaded point to the sampled point
  float distance = 0;
  float pdf = 0;       // solid angle, at the shaded point
  vec2 barycentric;    // triangle lights: (b1, b2) for texture lookups
};

// Samples a point of `light` visible-side-agnostic; false when the pdf is zero.
bool sample_area_light(const AreaLight& light, vec3 from, vec2 u, AreaLightSample& sample);
// Solid-angle pdf of sampling the point `on_light` (normal `light_normal`) from `from`.
float area_light_pdf(const AreaLight& light, vec3 from, vec3 on_light, vec3 light_normal);
// Whether the light emits towards `direction_to_viewer` from a point with normal `normal`.
inline bool area_light_emits(const AreaLight& light, vec3 normal, vec3 direction_to_viewer) {
  return light.two_sided || dot(normal, direction_to_viewer) > 0;
}

}  // namespace radiant
