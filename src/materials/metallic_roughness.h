// Quantities of the glTF metallic-roughness model shared by the Whitted mapping and the BSDF.
#pragma once

#include <algorithm>
#include <cmath>

#include "math/vec.h"

namespace radiant {

// Below this GGX alpha the specular lobes are treated as perfectly smooth (delta) lobes.
constexpr float smooth_alpha_threshold = 1e-3f;

// GGX alpha from glTF perceptual roughness (the glTF/Disney remapping alpha = roughness^2).
inline float roughness_to_alpha(float roughness) {
  float r = std::clamp(roughness, 0.0f, 1.0f);
  return r * r;
}

// Reflectance at normal incidence of a dielectric of index `ior` in air.
inline float dielectric_f0(float ior) {
  float ratio = (ior - 1) / (ior + 1);
  return ratio * ratio;
}

// Strength of the specular layer of an opaque dielectric: 1 for glossy surfaces, fading to 0 at
// roughness 1, so that a fully rough dielectric is exactly Lambertian in both integrators.
inline float dielectric_specular_fade(float roughness) {
  float r = std::clamp(roughness, 0.0f, 1.0f);
  float r2 = r * r, r4 = r2 * r2;
  return 1 - r4 * r4;
}

}  // namespace radiant
