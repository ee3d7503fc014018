// Flat faces of the .scene format: @triangle and @polygon, triangulated (ear clipping, concave
// polygons too) into one mesh per material with an identity instance.
#pragma once

#include <string>
#include <vector>

#include "scene_format/scene_format_context.h"

namespace radiant::scene_format {

// Why `vertices` (in order, at least 3) is not a planar polygon with an area; empty when it is.
// Tolerances scale with the polygon's size. (Whether it crosses itself is the triangulation's.)
std::string polygon_defect(const std::vector<vec3>& vertices);

// `@triangle` with `vertices` (9 numbers).
void build_triangle_block(BuildContext& context, const Block& block);
// `@polygon` with `vertices` (3 numbers per vertex, at least 3 vertices).
void build_polygon_block(BuildContext& context, const Block& block);

}  // namespace radiant::scene_format
