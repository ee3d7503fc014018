// Analytic shapes of the .scene format: @sphere, @wall / @plane, @cylinder, @tube.
#pragma once

#include <vector>

#include "scene_format/scene_format_values.h"

namespace radiant::scene_format {

// The block's own attribute names followed by the surface (material) attribute names.
std::vector<AttributeName> with_surface_names(std::vector<AttributeName> names);

void build_sphere_block(BuildContext& context, const Block& block);
// `@wall` (older format) and its alias `@plane`: an infinite plane.
void build_plane_block(BuildContext& context, const Block& block);
// A capped cylinder: base + axis + radius + height, or from + to + radius.
void build_cylinder_block(BuildContext& context, const Block& block);
// An infinite, uncapped tube: point + axis + radius.
void build_tube_block(BuildContext& context, const Block& block);

}  // namespace radiant::scene_format
