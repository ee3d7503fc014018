// The Charlie sheen distribution of KHR_materials_sheen (Estevez and Kulla 2017) with Ashikhmin's
// visibility term, as the Khronos sample viewer evaluates it, and its tabulated directional albedo.
#pragma once

#include "math/vec.h"

namespace radiant {

// The sheen BRDF times cosθi for a white sheen colour, in the local frame (z up); wo, wi above.
float eval_sheen(vec3 wo, vec3 wi, float sheen_roughness);
// Directional albedo E(cosθ) of that lobe (the extension's albedo-scaling term), interpolated
// in a table integrated once per process; in [0, 1].
float sheen_albedo(float cos_theta, float sheen_roughness);

}  // namespace radiant
