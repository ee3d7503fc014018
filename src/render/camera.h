// Camera rays: from a CameraDesc and an image size to one ray per film position.
#pragma once

#include <optional>

#include "accel/ray.h"
#include "materials/texture_footprint.h"
#include "render/render_options.h"
#include "scene/scene_desc.h"

namespace radiant {

struct CameraFrame {
  Projection projection = Projection::perspective;
  vec3 position, forward, right, up;
  float half_width = 1, half_height = 1;  // tan(half fov) for perspective, world units for ortho
  int width = 0, height = 0;
  float fisheye_half_angle = pi / 2;  // radians at the edge of the inscribed circle
  float lens_radius = 0, focus_distance = 1;
  int aperture_blades = 0;
};

CameraFrame make_camera_frame(const CameraDesc& camera, int width, int height);

// `still` moved to `pose` (a moving camera at a ray's time): its lens and field of view kept.
CameraFrame move_camera_frame(const CameraFrame& still, const CameraPose& pose);

// Ray through film position (x, y) in pixels, (0, 0) the top-left corner of the image, leaving
// the lens at the point `lens` in [0,1)^2 picks (ignored by a pinhole). nullopt where the
// projection sees nothing (outside a fisheye's circle).
std::optional<Ray> generate_camera_ray(const CameraFrame& frame, float x, float y, vec2 lens = {0.5f, 0.5f});

// The smallest spread between neighbouring pixels' rays over the image, searched along its
// diagonal through the lens centre as pbrt-v4's FindMinimumDifferentials does.
PixelSpread make_pixel_spread(const CameraFrame& frame);

// The box a framing camera (used when the file has no camera) must show: everything finite, and a
// point on each infinite plane and tube. False when there is nothing to frame.
bool framing_box(const SceneDesc& scene, vec3& lower, vec3& upper);

// A camera that sees all of the box [lower, upper] in an image of width / height `aspect`,
// looking across its two largest extents with `up` up, then turned by `orbit` about the box's
// centre (docs/cli.md, "The framing camera").
CameraDesc frame_box(vec3 lower, vec3 upper, float aspect, vec3 up = {0, 1, 0}, const Orbit& orbit = {});

// --camera frame: the framing camera, even when the file has cameras.
inline constexpr const char* framing_camera_name = "frame";

// Applies --look-from/--look-at/--up/--fov, --camera-type and the lens flags; throws
// std::invalid_argument on a degenerate view or a lens without a focus distance.
void apply_camera_override(CameraDesc& camera, const CameraOverride& override_);

// An orthographic camera that shows all of the box [lower, upper] in an image of width / height
// `aspect`, looking along its own direction: moved (unless `keep_position`) so that the box's
// centre is on its axis and every corner before its plane, and sized (unless `keep_height`) so
// that every corner is in view with a 5% margin.
void frame_orthographic(CameraDesc& camera, vec3 lower, vec3 upper, float aspect, bool keep_position, bool keep_height);

// Picks the camera by name or index among `cameras` ("" = the first, or `framing` when there is
// none; "frame" = `framing`; both set `framed`); throws std::invalid_argument when not found.
CameraDesc select_camera(const std::vector<CameraDesc>& cameras, const CameraDesc& framing, const std::string& which,
                         bool& framed);

}  // namespace radiant
