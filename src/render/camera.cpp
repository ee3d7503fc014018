#include "render/camera.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "sampling/warp.h"
#include "lights/environment_map.h"
#include "scene/coordinate_range.h"
#include "scene/scene_bounds.h"

namespace radiant {

namespace {

// Equirectangular: longitude from -pi (left edge) to pi, 0 at the image centre, along the
// view direction; latitude from pi/2 (top row, up) to -pi/2.
vec3 equirectangular_direction(const CameraFrame& f, float x, float y) {
  float longitude = (x / float(f.width) - 0.5f) * 2 * pi;
  float latitude = (0.5f - y / float(f.height)) * pi;
  float horizontal = std::cos(latitude);
  return f.forward * (horizontal * std::cos(longitude)) + f.right * (horizontal * std::sin(longitude)) +
         f.up * std::sin(latitude);
}

// Equidistant fisheye: the angle from the view direction grows linearly with the distance from
// the image centre, reaching the half field of view on the circle inscribed in the image.
std::optional<Ray> fisheye_ray(const CameraFrame& f, float x, float y) {
  float radius = 0.5f * float(std::min(f.width, f.height));
  float dx = (x - 0.5f * float(f.width)) / radius, dy = (0.5f * float(f.height) - y) / radius;
  float r = std::sqrt(dx * dx + dy * dy);
  if (r > 1) return std::nullopt;
  float theta = r * f.fisheye_half_angle;
  vec3 side = r > 0 ? (f.right * dx + f.up * dy) / r : f.right;
  return Ray{f.position, f.forward * std::cos(theta) + side * std::sin(theta)};
}

// A thin lens: the ray leaves a point of the aperture towards where the pinhole ray meets the
// plane in focus, so points on that plane stay sharp and others spread into the aperture's shape.
Ray through_lens(const CameraFrame& f, const Ray& pinhole, vec2 u) {
  vec2 aperture = f.aperture_blades >= 3 ? sample_regular_polygon(u, f.aperture_blades) : sample_uniform_disk(u);
  vec3 in_focus = pinhole.origin + pinhole.direction * (f.focus_distance / dot(pinhole.direction, f.forward));
  vec3 origin = pinhole.origin + (f.right * aperture.x + f.up * aperture.y) * f.lens_radius;
  return {origin, normalize(in_focus - origin)};
}

}  // namespace

CameraFrame make_camera_frame(const CameraDesc& camera, int width, int height) {
  CameraFrame f;
  f.projection = camera.projection;
  f.position = camera.position;
  f.forward = normalize(camera.forward);
  f.right = normalize(cross(f.forward, camera.up));
  f.up = cross(f.right, f.forward);
  f.width = width;
  f.height = height;
  float aspect = float(width) / float(height);
  if (camera.projection == Projection::perspective)
    f.half_height = std::tan(camera.vertical_fov_degrees * pi / 360.0f);
  else
    f.half_height = camera.ortho_height / 2;
  f.half_width = f.half_height * aspect;
  f.fisheye_half_angle = camera.fisheye_fov_degrees * pi / 360.0f;
  f.lens_radius = camera.lens_radius;
  f.focus_distance = camera.focus_distance;
  f.aperture_blades = camera.aperture_blades;
  return f;
}

std::optional<Ray> generate_camera_ray(const CameraFrame& f, float x, float y, vec2 lens) {
  if (f.projection == Projection::equirectangular) return Ray{f.position, equirectangular_direction(f, x, y)};
  if (f.projection == Projection::fisheye) return fisheye_ray(f, x, y);
  float sx = (2 * x / float(f.width) - 1) * f.half_width;
  float sy = (1 - 2 * y / float(f.height)) * f.half_height;
  Ray pinhole = f.projection == Projection::orthographic ? Ray{f.position + f.right * sx + f.up * sy, f.forward}
                                                         : Ray{f.position, normalize(f.forward + f.right * sx + f.up * sy)};
  return f.lens_radius > 0 ? through_lens(f, pinhole, lens) : pinhole;
}

CameraFrame move_camera_frame(const CameraFrame& still, const CameraPose& pose) {
  CameraFrame f = still;
  f.position = pose.position;
  f.forward = pose.forward;
  f.right = normalize(cross(f.forward, pose.up));
  f.up = cross(f.right, f.forward);
  return f;
}

bool framing_box(const SceneDesc& scene, vec3& lower, vec3& upper) {
  bool finite = scene_bounds(scene, lower, upper);
  // Infinite planes and tubes: frame a point on each, so a scene of only planes is seen.
  for (const ShapeDesc& s : scene.shapes)
    if (s.kind == ShapeKind::plane || s.kind == ShapeKind::tube) {
      lower = finite ? min(lower, s.center) : s.center;
      upper = finite ? max(upper, s.center) : s.center;
      finite = true;
    }
  return finite;
}

// The area of the box's silhouette seen along unit direction `d` (the faces it sees, projected).
static float projected_box_area(vec3 extent, vec3 d) {
  return std::abs(d.x) * extent.y * extent.z + std::abs(d.y) * extent.x * extent.z + std::abs(d.z) * extent.x * extent.y;
}

CameraDesc frame_box(vec3 lower, vec3 upper, float aspect, vec3 up, const Orbit& orbit) {
  CameraDesc camera;
  camera.name = "framing";
  camera.vertical_fov_degrees = 40;
  // The view is worked out in the world's own axes for `up` (the environment's: y up, +z the
  // front), so a z-up model is framed as a y-up one is.
  EnvironmentFrame axes = make_environment_frame(up, 0);
  vec3 center = (lower + upper) * 0.5f, corners[8], extent;
  for (int corner = 0; corner < 8; ++corner) {
    vec3 p = {corner & 1 ? upper.x : lower.x, corner & 2 ? upper.y : lower.y, corner & 4 ? upper.z : lower.z};
    corners[corner] = to_environment(axes, p - center);
    extent = max(extent, abs(corners[corner]) * 2);
  }
  // From the front (+z, the glTF front) a little above, so that depth shows, unless the side (+x)
  // or the view from above shows more than twice the box's area there: a flat model is seen face
  // on, never edge on, and a long low one keeps its front view.
  vec3 toward_camera = normalize(vec3{0, 0.25f, 1});
  float front_area = projected_box_area(extent, toward_camera), best_area = 2 * front_area;
  for (vec3 view : {normalize(vec3{1, 0.25f, 0}), normalize(vec3{0, 1, 0.25f})})
    if (float area = projected_box_area(extent, view); area > best_area) toward_camera = view, best_area = area;
  if (orbit.azimuth_degrees != 0 || orbit.elevation_degrees != 0) {
    constexpr float degree = pi / 180;
    float azimuth = std::atan2(toward_camera.x, toward_camera.z) + orbit.azimuth_degrees * degree;
    float elevation = std::clamp(std::asin(toward_camera.y) + orbit.elevation_degrees * degree, -89.9f * degree,
                                 89.9f * degree);
    toward_camera = {std::cos(elevation) * std::sin(azimuth), std::sin(elevation), std::cos(elevation) * std::cos(azimuth)};
  }
  vec3 forward = -toward_camera;
  vec3 camera_up = normalize(cross(cross(forward, vec3{0, 1, 0}), forward));
  vec3 right = cross(forward, camera_up);
  // Every corner inside the view, with a margin of 5%: a corner at depth `along` before the
  // centre needs the camera `offset / tan(half angle)` farther than that.
  float tan_vertical = std::tan(camera.vertical_fov_degrees * pi / 360.0f);
  float tan_horizontal = tan_vertical * std::max(aspect, 1e-3f);
  float distance = 1e-6f * std::max(1.0f, max_component(abs(center)));
  for (vec3 d : corners) {
    float needed = std::max(std::abs(dot(d, camera_up)) / tan_vertical, std::abs(dot(d, right)) / tan_horizontal);
    distance = std::max(distance, dot(d, toward_camera) + 1.05f * needed);
  }
  camera.position = center + from_environment(axes, toward_camera * (distance * orbit.distance));
  camera.forward = from_environment(axes, forward);
  camera.up = from_environment(axes, camera_up);
  return camera;
}

// Positions given on the command line obey the scene's coordinate range.
void check_override_range(const std::optional<vec3>& point, const char* flag) {
  if (point && !(max_component(abs(*point)) <= max_scene_coordinate))
    throw std::invalid_argument(std::string(flag) + " lies beyond the supported range of coordinates (magnitude up to " +
                                max_scene_coordinate_text + ")");
}

namespace {

// --fov: a fisheye's whole field of view, or the vertical one of a perspective camera (an
// orthographic camera given a field of view becomes perspective).
void apply_fov(CameraDesc& camera, float degrees) {
  if (camera.projection == Projection::equirectangular)
    throw std::invalid_argument("--fov does not apply to an equirectangular camera (it sees all around)");
  if (camera.projection == Projection::fisheye) {
    if (!(degrees > 0 && degrees <= 360)) throw std::invalid_argument("--fov of a fisheye must be in (0, 360] degrees");
    camera.fisheye_fov_degrees = degrees;
    return;
  }
  if (!(degrees > 0 && degrees < 180)) throw std::invalid_argument("--fov must be in (0, 180) degrees");
  camera.vertical_fov_degrees = degrees;
  camera.projection = Projection::perspective;
}

// --lens-radius, --focus-distance and --blades; with --look-at, focus defaults to the point looked at.
void apply_lens(CameraDesc& camera, const CameraOverride& o) {
  if (o.lens_radius) camera.lens_radius = *o.lens_radius;
  if (o.focus_distance) camera.focus_distance = *o.focus_distance;
  else if (o.look_at && o.lens_radius) camera.focus_distance = dot(*o.look_at - camera.position, camera.forward);
  if (o.aperture_blades) camera.aperture_blades = *o.aperture_blades;
  if (camera.lens_radius <= 0) return;
  bool panorama = camera.projection == Projection::equirectangular || camera.projection == Projection::fisheye;
  if (panorama) throw std::invalid_argument("a lens (--lens-radius) needs a perspective or orthographic camera");
  if (!(camera.focus_distance > 0))
    throw std::invalid_argument("a lens (--lens-radius) needs a focus distance: --focus-distance D, or --look-at");
}

}  // namespace

void apply_camera_override(CameraDesc& camera, const CameraOverride& o) {
  check_override_range(o.look_from, "--look-from");
  check_override_range(o.look_at, "--look-at");
  if (o.look_from || o.look_at) camera.motion.clear();  // placed by the flags: it no longer follows the file
  if (o.look_from) camera.position = *o.look_from;
  if (o.look_at) {
    vec3 d = *o.look_at - camera.position;
    if (length(d) == 0 || !is_finite(d)) throw std::invalid_argument("--look-at equals the camera position");
    camera.forward = normalize(d);
  }
  if (o.up && !(length(*o.up) > 0 && is_finite(*o.up))) throw std::invalid_argument("--up must be a non-zero vector");
  vec3 up = o.up ? *o.up : camera.up;
  if (o.projection && *o.projection != camera.projection) {
    camera.projection = *o.projection;
    // The file's image size belongs to its own projection. Default shapes: the whole sphere at
    // equal angular steps, the fisheye's circle, the file's aspect otherwise.
    camera.width = camera.height = 0;
    if (camera.projection == Projection::equirectangular) camera.aspect = 2;
    if (camera.projection == Projection::fisheye) camera.aspect = 1;
  }
  if (o.fov_degrees) apply_fov(camera, *o.fov_degrees);
  if (o.ortho_height) {
    if (camera.projection != Projection::orthographic)
      throw std::invalid_argument("--ortho-height sizes an orthographic view: add --camera-type orthographic");
    camera.ortho_height = *o.ortho_height;
  }
  apply_lens(camera, o);
  vec3 right = cross(camera.forward, up);
  if (!(length(right) > 1e-6f * length(up))) {
    if (o.up) throw std::invalid_argument("--up is parallel to the view direction");
    // Keep the authored up's intent when only the direction changed: fall back to +z or +x.
    up = std::abs(camera.forward.y) < 0.999f ? vec3{0, 1, 0} : vec3{0, 0, -1};
    right = cross(camera.forward, up);
  }
  camera.up = normalize(cross(normalize(right), camera.forward));
}

void frame_orthographic(CameraDesc& camera, vec3 lower, vec3 upper, float aspect, bool keep_position, bool keep_height) {
  vec3 right = normalize(cross(camera.forward, camera.up));
  vec3 center = (lower + upper) * 0.5f;
  // The view's axis passes through the box's centre, or the camera's own place when it was given.
  vec3 axis_point = keep_position ? camera.position : center;
  float half_up = 0, half_right = 0, depth = 0;
  for (int corner = 0; corner < 8; ++corner) {
    vec3 d = vec3{corner & 1 ? upper.x : lower.x, corner & 2 ? upper.y : lower.y, corner & 4 ? upper.z : lower.z} - axis_point;
    half_up = std::max(half_up, std::abs(dot(d, camera.up)));
    half_right = std::max(half_right, std::abs(dot(d, right)));
    depth = std::max(depth, -dot(d, camera.forward));
  }
  // Rays start on the camera's plane: it stands before every corner, by a 5% margin.
  if (!keep_position) camera.position = center - camera.forward * (1.05f * depth + 1e-6f * std::max(1.0f, max_component(abs(center))));
  // Every corner inside the view, with the framing camera's 5% margin.
  float height = 2 * 1.05f * std::max(half_up, half_right / std::max(aspect, 1e-3f));
  if (!keep_height && height > 0) camera.ortho_height = height;
}

CameraDesc select_camera(const std::vector<CameraDesc>& cameras, const CameraDesc& framing, const std::string& which,
                         bool& framed) {
  framed = false;
  if (which == framing_camera_name) {
    framed = true;
    return framing;
  }
  if (which.empty()) {
    if (!cameras.empty()) return cameras.front();
    framed = true;
    return framing;
  }
  for (const CameraDesc& c : cameras)
    if (c.name == which) return c;
  bool numeric = !which.empty() && which.find_first_not_of("0123456789") == std::string::npos;
  if (numeric) {
    size_t index = std::stoul(which);
    if (index < cameras.size()) return cameras[index];
  }
  std::string known;
  for (size_t i = 0; i < cameras.size(); ++i)
    known += (i ? ", " : "") + std::to_string(i) + (cameras[i].name.empty() ? "" : " '" + cameras[i].name + "'");
  throw std::invalid_argument("no camera '" + which + "' in the scene (cameras: " + (known.empty() ? "none" : known) + ")");
}

}  // namespace radiant
