// Materials of the .scene format: `@material NAME` blocks, and the material of each shape
// (a named one, inline Phong attributes, or the older format's c/e/s).
#pragma once

#include <vector>

#include "scene_format/scene_format_values.h"

namespace radiant::scene_format {

// Attribute names every shape block accepts for its material.
const std::vector<AttributeName>& surface_attribute_names();

// `@material NAME` with kd, ks, ka, kr, kt, shininess, ior, emission.
void build_material_block(BuildContext& context, const Block& block);

// The material index for a shape from its surface attributes; adds a material when needed.
int surface_material(BuildContext& context, const Attributes& attributes);

// True when the shape gave any surface attribute (used by @mesh to keep the OBJ's materials).
bool has_surface_attributes(const Attributes& attributes);

}  // namespace radiant::scene_format
