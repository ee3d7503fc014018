// Thin-film interference as KHR_materials_iridescence defines it: the two-interface Airy sum,
// with the spectral integral of its cosine terms done in Fourier space against Gaussian fits of
// the CIE XYZ sensitivities, then converted to Rec. 709.
#include "materials/thin_film.h"

#include <algorithm>
#include <cmath>

namespace radiant {

namespace {

float square(float x) { return x * x; }

float schlick(float f0, float cos) {
  float m = 1 - std::clamp(cos, 0.0f, 1.0f);
  return f0 + (1 - f0) * (m * m) * (m * m) * m;
}

// Reflectance at normal incidence between media of indices a and b.
float normal_reflectance(float a, float b) { return square((a - b) / (a + b)); }

// The index that gives reflectance f0 against air (the inverse of normal_reflectance(n, 1)).
float index_from_reflectance(float f0) {
  float root = std::sqrt(std::clamp(f0, 0.0f, 0.9999f));
  return (1 + root) / (1 - root);
}

// The XYZ sensitivity's Fourier transform at optical path difference `opd` (nm) with phase
// `shift`, as Rec. 709: the extension's Gaussian fits (three lobes and a second one for X).
color3 spectral_sensitivity(float opd, color3 shift) {
  constexpr float val[3] = {5.4856e-13f, 4.4201e-13f, 5.2481e-13f};
  constexpr float pos[3] = {1.6810e+06f, 1.7953e+06f, 2.2084e+06f};
  constexpr float var[3] = {4.3278e+09f, 9.3046e+09f, 6.6121e+09f};
  double phase = 2 * pi * double(opd) * 1e-9;
  double xyz[3];
  for (int c = 0; c < 3; ++c)
    xyz[c] = val[c] * std::sqrt(2 * pi * var[c]) * std::cos(pos[c] * phase + shift[c]) * std::exp(-phase * phase * var[c]);
  xyz[0] += 9.7470e-14 * std::sqrt(2 * pi * 4.5282e+09) * std::cos(2.2399e+06 * phase + shift[0]) *
            std::exp(-4.5282e+09 * phase * phase);
  for (double& v : xyz) v /= 1.0685e-7;
  return {float(3.2404542 * xyz[0] - 1.5371385 * xyz[1] - 0.4985314 * xyz[2]),
          float(-0.9692660 * xyz[0] + 1.8760108 * xyz[1] + 0.0415560 * xyz[2]),
          float(0.0556434 * xyz[0] - 0.2040259 * xyz[1] + 1.0572252 * xyz[2])};
}

}  // namespace

color3 thin_film_fresnel(float cos_outside, float outside_ior, const ThinFilm& film, color3 base_f0) {
  float cos1 = std::clamp(cos_outside, 0.0f, 1.0f);
  float sin2_film = square(outside_ior / film.ior) * (1 - cos1 * cos1);
  if (sin2_film >= 1) return {1, 1, 1};  // total internal reflection at the film
  float cos2 = std::sqrt(1 - sin2_film);
  // First interface (outside to film), the same both ways.
  float r12 = schlick(normal_reflectance(film.ior, outside_ior), cos1);
  float t121 = 1 - r12;
  float phi21 = film.ior < outside_ior ? 0 : pi;  // pi minus the phase of the way in
  // The optical path difference between a reflection at the base and one at the film's top.
  float opd = 2 * film.ior * film.thickness_nm * cos2;
  // Per channel: the base's interface, the phase shift of a round trip, and the Airy terms.
  color3 phi, amplitude, reflectance, root_r123;
  for (int c = 0; c < 3; ++c) {
    float base_ior = index_from_reflectance(base_f0[c]);
    float r23 = schlick(normal_reflectance(base_ior, film.ior), cos2);
    phi[c] = phi21 + (base_ior < film.ior ? pi : 0);
    float r123 = std::clamp(r12 * r23, 1e-5f, 0.9999f);
    float through = square(t121) * r23 / (1 - r123);  // the base's share, summed over bounces
    reflectance[c] = r12 + through;                   // m = 0: no interference
    amplitude[c] = through - t121;
    root_r123[c] = std::sqrt(r123);
  }
  // m = 1, 2: the interference terms (the shift of channel c applies to the c-th XYZ lobe, as
  // the extension's evalSensitivity does).
  for (int m = 1; m <= 2; ++m) {
    amplitude *= root_r123;
    reflectance += amplitude * spectral_sensitivity(float(m) * opd, phi * float(m)) * 2.0f;
  }
  reflectance = max(reflectance, {0, 0, 0});
  return reflectance;
}

}  // namespace radiant
