// Fresnel reflectance for dielectric interfaces and Schlick's approximation for conductors,
// written over a lane (math/lane.h): the single path and the batch's SIMD lanes call the same code.
#pragma once

#include <algorithm>
#include <cmath>

#include "math/lane.h"
#include "math/vec.h"

namespace radiant {

// Unpolarized Fresnel reflectance of a dielectric interface; `cos_i` > 0 on the incident side and
// `eta` = n_transmitted / n_incident. Returns 1 on total internal reflection (the square root's
// NaN there is worked out and not selected).
[[gnu::always_inline]] inline float fresnel_dielectric(float cos_i, float eta) {
  cos_i = std::clamp(cos_i, 0.0f, 1.0f);
  float sin2_t = (1 - cos_i * cos_i) / (eta * eta);
  float cos_t = std::sqrt(1 - sin2_t);
  float parallel = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  float perpendicular = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  float reflectance = (parallel * parallel + perpendicular * perpendicular) / 2;
  return sin2_t >= 1 ? 1.0f : reflectance;
}

// The dielectric curve of `ior` rescaled to run from 0 at normal incidence to 1 at grazing
// (KHR_materials_specular's coating), `f0` being the ior's own reflectance at normal incidence.
[[gnu::always_inline]] inline float fresnel_rise(float cos_i, float ior, float f0) {
  float rise = std::max((fresnel_dielectric(cos_i, ior) - f0) / (1 - f0), 0.0f);
  return f0 < 1 ? rise : 1.0f;
}

// Schlick's approximation with a colored reflectance at normal incidence (metals).
[[gnu::always_inline]] inline color3 fresnel_schlick(color3 f0, float cos_i) {
  float m = 1 - std::clamp(cos_i, 0.0f, 1.0f);
  float m5 = (m * m) * (m * m) * m;
  return f0 + (color3{1, 1, 1} - f0) * m5;
}

}  // namespace radiant
