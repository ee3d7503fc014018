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

// KHR_materials_specular's F0 of a dielectric: the ior's F0 tinted by the specular color, at
// most 1 per channel (the extension's min(F0 · specularColor, 1)).
inline color3 tinted_dielectric_f0(float ior, color3 specular_color) {
  float f0 = dielectric_f0(ior);
  return min(max(specular_color * f0, {0, 0, 0}), {1, 1, 1});
}

}  // namespace radiant
