// The camera's pixel spread for texture footprints (materials/texture_footprint.h).
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "render/camera.h"

namespace radiant {

PixelSpread make_pixel_spread(const CameraFrame& frame) {
  PixelSpread spread;
  spread.camera_position = frame.position;
  spread.forward = frame.forward, spread.right = frame.right, spread.up = frame.up;
  spread.parallel = frame.projection == Projection::orthographic;
  float inf = std::numeric_limits<float>::infinity();
  float origin_x = inf, origin_y = inf, direction_x = inf, direction_y = inf;
  constexpr int steps = 64;
  for (int i = 0; i < steps; ++i) {
    float x = float(i) / (steps - 1) * float(frame.width), y = float(i) / (steps - 1) * float(frame.height);
    std::optional<Ray> ray = generate_camera_ray(frame, x, y);
    std::optional<Ray> ray_x = generate_camera_ray(frame, x + 1, y);
    std::optional<Ray> ray_y = generate_camera_ray(frame, x, y + 1);
    if (!ray || !ray_x || !ray_y) continue;  // outside a fisheye's circle
    vec3 d = normalize(ray->direction);
    origin_x = std::min(origin_x, length(ray_x->origin - ray->origin));
    origin_y = std::min(origin_y, length(ray_y->origin - ray->origin));
    direction_x = std::min(direction_x, length(normalize(ray_x->direction) - d));
    direction_y = std::min(direction_y, length(normalize(ray_y->direction) - d));
  }
  if (!std::isfinite(origin_x) || !std::isfinite(direction_x)) return spread;  // no ray: no footprint
  spread.origin_step_x = origin_x, spread.origin_step_y = origin_y;
  spread.direction_step_x = direction_x, spread.direction_step_y = direction_y;
  return spread;
}

}  // namespace radiant
