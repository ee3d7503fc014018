// Cameras of the .scene format: the older `@viewer` and the `@camera` extension.
#pragma once

#include "scene_format/scene_format_context.h"

namespace radiant::scene_format {

// Vertical field of view of `@viewer`, which has no attribute for it.
constexpr float viewer_vertical_fov_degrees = 60;
// Vertical field of view of `@camera` when neither `fov` nor a view plane is given.
constexpr float camera_default_fov_degrees = 60;

// `@viewer` with `p` (position) and `f` (facing direction); up is +y or the fallback of
// `default_up`.
void build_viewer_block(BuildContext& context, const Block& block);

// `@camera [NAME]` with position, direction or look-at, up, fov or view-distance + view-size,
// orthographic, resolution.
void build_camera_block(BuildContext& context, const Block& block);

// +y, unless `forward` is (nearly) parallel to it: then (0, 0, sign(forward.y)), the up of a
// camera pitched from looking down -z to looking straight up or down.
vec3 default_up(vec3 forward);

}  // namespace radiant::scene_format
