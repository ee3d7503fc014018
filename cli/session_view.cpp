#include "session_view.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "math/transform.h"

namespace radiant::cli {

namespace {

// An up orthogonal to `direction`, as close to `wanted` as can be (another axis when they align).
vec3 orthogonal_up(vec3 direction, vec3 wanted) {
  vec3 forward = normalize(direction);
  vec3 right = cross(forward, normalize(wanted));
  if (!(length(right) > 1e-6f)) right = cross(forward, std::abs(forward.y) < 0.999f ? vec3{0, 1, 0} : vec3{0, 0, -1});
  return normalize(cross(normalize(right), forward));
}

bool parallel(vec3 a, vec3 b) { return !(length(cross(normalize(a), normalize(b))) > 1e-6f); }

}  // namespace

SessionView view_of(const CameraDesc& camera) { return {camera.position, camera.forward, camera.up}; }

void move_to(SessionView& view, vec3 position) { view.position = position; }

void move_by(SessionView& view, vec3 offset) { view.position = view.position + offset; }

void turn_to(SessionView& view, vec3 direction) {
  if (!is_finite(direction) || !(length(direction) > 0)) throw std::invalid_argument("turnto needs a non-zero direction");
  view.direction = direction;
  if (parallel(view.direction, view.up)) view.up = orthogonal_up(view.direction, view.up);
}

void turn_by(SessionView& view, vec3 degrees) {
  mat4 rotation = rotation_axis({0, 0, 1}, degrees.z) * rotation_axis({0, 1, 0}, degrees.y) *
                  rotation_axis({1, 0, 0}, degrees.x);
  view.direction = normalize(transform_vector(rotation, view.direction));
  view.up = orthogonal_up(view.direction, transform_vector(rotation, view.up));
}

CameraOverride camera_override(const SessionView& view) {
  float far = std::max({1.0f, std::abs(view.position.x), std::abs(view.position.y), std::abs(view.position.z)});
  vec3 ahead = view.direction;
  while (length(ahead) < far) ahead = ahead * 2.0f;
  CameraOverride o;
  o.look_from = view.position;
  o.look_at = view.position + ahead;
  o.up = view.up;
  return o;
}

}  // namespace radiant::cli
