// Lines and points (scene/scene_desc.h StrokeDesc) as Embree geometry: round linear curves and
// sphere points, each vertex with the radius its width asks for. A width in pixels becomes a
// radius at each vertex from its distance to the camera, so that a line keeps about that many
// pixels across wherever it lies, as viewers draw lines.
#pragma once

#include <embree3/rtcore.h>

#include <vector>

#include "scene/scene_desc.h"

namespace radiant {

// --line-width: how wide a stroke without a width of its own is drawn.
struct LineWidth {
  float value = 1;
  bool in_pixels = true;  // false: world units
};

// What turns pixels into world units at a point: one pixel's size at distance d from the camera
// is per_unit_distance × d + constant (perspective and panoramic views grow with distance,
// orthographic ones do not).
struct PixelFootprint {
  vec3 camera = {0, 0, 0};
  float per_unit_distance = 0;
  float constant = 0;
};

// How the accelerator sizes strokes: the render's --line-width and the view's pixel footprint.
struct StrokeSizing {
  LineWidth line_width;
  PixelFootprint footprint;
};

// The radius of `stroke` at its vertex `i` (half the width).
float stroke_radius(const StrokeDesc& stroke, size_t i, const StrokeSizing& sizing);

// The geometry of `stroke`, committed; its largest radius in `max_radius`.
RTCGeometry new_stroke_geometry(RTCDevice device, const StrokeDesc& stroke, const StrokeSizing& sizing,
                                float& max_radius);

}  // namespace radiant
