// How wide lines and points are drawn for a view: --line-width, and for widths in pixels the
// world size of a pixel at each vertex's distance from the view's camera.
#pragma once

#include "accel/stroke_geometry.h"
#include "math/dvec3.h"
#include "math/vec.h"
#include "scene/scene_desc.h"

namespace radiant {

// One pixel's world size for `camera` (at render-space `position`) in an image `height` tall.
PixelFootprint pixel_footprint(const CameraDesc& camera, vec3 position, int height);
// How a view sizes lines and points `width` pixels wide: `camera` (world space) seeing an image
// `height` tall, the scene placed in the render space of `origin`.
StrokeSizing stroke_sizing_in_pixels(LineWidth width, const CameraDesc& camera, int height, dvec3 origin);
bool same_sizing(const StrokeSizing& a, const StrokeSizing& b);

}  // namespace radiant
