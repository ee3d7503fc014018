// Lines and points of the .scene format: @line (a polyline, closed or not) and @points.
#pragma once

#include "scene_format/scene_format_values.h"

namespace radiant::scene_format {

// `vertices` (two or more), `closed` to join the last back to the first, `width` in scene units.
void build_line_block(BuildContext& context, const Block& block);
// `vertices` (one or more), each a sphere `width` across.
void build_points_block(BuildContext& context, const Block& block);

}  // namespace radiant::scene_format
