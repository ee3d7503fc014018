#include "render/stroke_sizing.h"

#include <cmath>

#include "render/render_space.h"

namespace radiant {

// At unit distance for the projections that widen with distance, everywhere for the orthographic one.
PixelFootprint pixel_footprint(const CameraDesc& camera, vec3 position, int height) {
  PixelFootprint f;
  f.camera = position;
  switch (camera.projection) {
    case Projection::perspective:
      f.per_unit_distance = 2 * std::tan(camera.vertical_fov_degrees * pi / 360) / float(height);
      break;
    case Projection::orthographic: f.constant = camera.ortho_height / float(height); break;
    case Projection::equirectangular: f.per_unit_distance = pi / float(height); break;
    case Projection::fisheye: f.per_unit_distance = camera.fisheye_fov_degrees * pi / 180 / float(height); break;
  }
  return f;
}

StrokeSizing stroke_sizing_in_pixels(LineWidth width, const CameraDesc& camera, int height, dvec3 origin) {
  return {width, pixel_footprint(camera, to_render_space(camera.position, origin), height)};
}

bool same_sizing(const StrokeSizing& a, const StrokeSizing& b) {
  return a.line_width.value == b.line_width.value && a.line_width.in_pixels == b.line_width.in_pixels &&
         a.footprint.camera == b.footprint.camera && a.footprint.per_unit_distance == b.footprint.per_unit_distance &&
         a.footprint.constant == b.footprint.constant;
}

}  // namespace radiant
