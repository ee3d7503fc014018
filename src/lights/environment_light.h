// Sampling directions towards the environment: uniform over the sphere for a constant color,
// by luminance for a map (a mixture when both are present).
#pragma once

#include "lights/light_table.h"

namespace radiant {

// Samples a unit direction; returns its solid-angle pdf (0 when nothing can be sampled).
float sample_environment(const LightTable& lights, float u_choice, vec2 u, vec3& direction);
float environment_pdf(const LightTable& lights, vec3 direction);

}  // namespace radiant
