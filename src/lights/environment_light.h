// Sampling directions towards the environment: the constant color part cosine-weighted around
// the shaded point's normal (exact for diffuse surfaces under a uniform sky), a map by its
// luminance; a mixture of the two when both are present.
#pragma once

#include "lights/light_table.h"

namespace radiant {

// Samples a unit direction; returns its solid-angle pdf (0 when nothing can be sampled).
float sample_environment(const LightTable& lights, vec3 normal, float u_choice, vec2 u, vec3& direction);
// Solid-angle pdf of `direction` as sampled from a point with shading normal `normal`.
float environment_pdf(const LightTable& lights, vec3 normal, vec3 direction);
// Environment radiance seen along unit direction `d`.
color3 eval_environment(const LightTable& lights, vec3 d);
// The same through the map's blurred backdrop: what --background blur shows camera rays.
color3 eval_environment_backdrop(const LightTable& lights, vec3 d);

}  // namespace radiant
