// KHR_materials_volume's absorption coefficient: the per-channel sigma with which light inside a
// closed transmissive mesh keeps exp(-sigma * distance) of itself (Beer-Lambert).
#pragma once

#include <algorithm>
#include <cmath>

#include "scene/scene_desc.h"

namespace radiant {

// Sigma = -ln(attenuation colour) / attenuation distance; 0 without a volume (no transmission, a
// thin wall, or an infinite distance). A colour channel of 0 absorbs everything (very large sigma).
inline color3 volume_absorption(const MaterialDesc& m) {
  bool volume = m.model == MaterialModel::metallic_roughness && m.transmission > 0 && m.thickness > 0 &&
                m.attenuation_distance > 0;
  if (!volume) return {0, 0, 0};
  color3 sigma;
  for (int c = 0; c < 3; ++c)
    sigma[c] = -std::log(std::clamp(m.attenuation_color[c], 1e-30f, 1.0f)) / m.attenuation_distance;
  return sigma;
}

}  // namespace radiant
