// KHR_materials_iridescence: the Fresnel reflectance of a base under a thin dielectric film, with
// the interference of light reflected at its two interfaces integrated over the visible spectrum
// analytically (Belcour and Barla 2017, in the approximation the extension states: Schlick's
// Fresnel per interface, no polarization, phase shifts of 0 or pi).
#pragma once

#include "math/vec.h"

namespace radiant {

struct ThinFilm {
  float ior = 1.3f;           // of the film
  float thickness_nm = 400;  // of the film, in nanometres
};

// Reflectance at cosine `cos_outside` (measured outside the film, whose medium has index
// `outside_ior`) of a base whose normal-incidence reflectance is `base_f0`, in linear Rec. 709.
color3 thin_film_fresnel(float cos_outside, float outside_ior, const ThinFilm& film, color3 base_f0);

}  // namespace radiant
