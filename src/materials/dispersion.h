// KHR_materials_dispersion: a transmissive material's index of refraction per wavelength, from
// its Abbe number, and the wavelengths radiant's three colour channels stand for.
#pragma once

#include <algorithm>

namespace radiant {

// The dominant wavelengths (nm) of the sRGB/Rec.709 red, green and blue primaries: the path
// tracer follows one of them through a dispersive surface (docs/materials.md).
constexpr float channel_wavelengths_nm[3] = {611.3f, 549.1f, 464.3f};

// The extension's n(λ) = max(n_d + (n_d − 1) / V_d · (523655 / λ² − 1.5168), 1), where `ior`
// is n_d (at 587.6 nm) and `dispersion` is 20 / V_d; dispersion 0 gives `ior` unchanged.
inline float dispersive_ior(float ior, float dispersion, float wavelength_nm) {
  if (!(dispersion > 0)) return ior;
  float cauchy = 523655.0f / (wavelength_nm * wavelength_nm) - 1.5168f;
  return std::max(ior + (ior - 1) * (dispersion / 20) * cauchy, 1.0f);
}

}  // namespace radiant
