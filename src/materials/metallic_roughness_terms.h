// Terms of the glTF metallic-roughness BSDF written once over a lane (math/lane.h), for its
// one-path model (metallic_roughness_bsdf.cpp) and its SIMD lanes (metallic_roughness_lane.h).
#pragma once

#include <algorithm>

#include "math/vec.h"

namespace radiant {

// Smallest selection weight of a present non-delta lobe: its pdf must never be 0 where it scatters.
constexpr float min_lobe_weight = 0.05f;

// A lobe's weight in the choice between lobes: its reflectance estimate, 0 where the material
// has no such lobe. Delta lobes need no floor: a delta lobe with no reflectance is never chosen.
[[gnu::always_inline]] inline float selection_weight(bool present, float estimate, bool delta) {
  float weight = delta ? estimate : std::max(estimate, min_lobe_weight);
  return present ? weight : 0.0f;
}

// The plastic's coating reflectance (KHR_materials_specular) before its strength: the coating's
// Fresnel curve, whose value `rise` runs from 0 at normal incidence to 1 at grazing, taking the
// tinted F0 `specular_f0` to 1.
[[gnu::always_inline]] inline color3 tinted_coating_reflectance(color3 specular_f0, float rise) {
  return specular_f0 + (color3{1, 1, 1} - specular_f0) * rise;
}

}  // namespace radiant
