// How wide lines and points are drawn for a view: --line-width, and for widths in pixels the
// world size of a pixel at each vertex's distance from the view's camera.
#pragma once

#include "render/render.h"

namespace radiant {

// One pixel's world size for `camera` (at render-space `position`) in an image `height` tall.
PixelFootprint pixel_footprint(const CameraDesc& camera, vec3 position, int height);
// How the view of `options` sizes the prepared scene's lines and points (in its render space).
StrokeSizing stroke_sizing_for(const PreparedScene& prepared, const RenderOptions& options);
bool same_sizing(const StrokeSizing& a, const StrokeSizing& b);

}  // namespace radiant
