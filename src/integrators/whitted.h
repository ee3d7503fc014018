// The Phong/Whitted ray tracer: emission, ambient, Phong direct light per light with shadows
// through transparent occluders, and recursive mirror reflection and refraction.
#pragma once

#include "integrators/render_context.h"

namespace radiant {

// The Whitted variant compiled for the smallest effect set covering `effects`.
Integrator select_whitted(uint32_t effects);

}  // namespace radiant
