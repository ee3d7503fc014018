#include "scene_format/scene_format_camera.h"

#include <utility>

#include "scene_format/scene_format_units.h"
#include "scene_format/scene_format_values.h"

namespace radiant::scene_format {

// Sine of the smallest angle between view direction and up that still defines a frame.
constexpr float min_up_sine = 1e-4f;

vec3 default_up(vec3 forward) {
  vec3 up = {0, 1, 0};
  if (length(cross(forward, up)) >= min_up_sine) return up;
  return {0, 0, forward.y > 0 ? 1.0f : -1.0f};
}

// The camera frame: `up` made orthogonal to the unit `forward`. A given up parallel to the view
// direction is an error at its line; a missing one falls back to `default_up`.
static void set_frame(const BuildContext& context, CameraDesc& camera, vec3 forward, const Attribute* up) {
  vec3 up_direction = up ? read_direction(context, *up) : default_up(forward);
  vec3 side = cross(forward, up_direction);
  if (length(side) < min_up_sine)
    fail(context, up->name, quote(up->name.text) + " is parallel to the view direction");
  camera.forward = forward;
  camera.up = normalize(cross(normalize(side), forward));
}

void build_viewer_block(BuildContext& context, const Block& block) {
  expect_block_arguments(context, block, 0);
  Attributes attributes = index_attributes(context, block, {{"p", ""}, {"f", ""}}, "@viewer");
  CameraDesc camera;
  camera.name = "viewer";
  camera.position = read_vec3(context, require(context, attributes, "p", "@viewer"));
  set_frame(context, camera, read_direction(context, require(context, attributes, "f", "@viewer")), nullptr);
  camera.vertical_fov_degrees = viewer_vertical_fov_degrees;
  context.scene.cameras.push_back(camera);
}

static const std::vector<AttributeName> camera_names = {
    {"position", ""}, {"direction", ""},     {"look-at", ""},   {"up", ""},         {"fov", ""},
    {"view-distance", ""}, {"view-size", ""}, {"resolution", ""}, {"orthographic", ""},
    {"lens-radius", ""}, {"focus-distance", ""}, {"blades", ""}, {"panorama", ""}, {"fisheye-fov", ""}};

// Fails at the later of the two attributes when both are given.
static void exclusive(const BuildContext& context, const Attribute* first, const Attribute* second) {
  if (!first || !second) return;
  if (first->name.line > second->name.line) std::swap(first, second);
  fail(context, second->name, quote(second->name.text) + " cannot be combined with " + quote(first->name.text));
}

static vec3 camera_forward(const BuildContext& context, const Attributes& attributes, vec3 position) {
  const Attribute* direction = find(attributes, "direction");
  const Attribute* look_at = find(attributes, "look-at");
  exclusive(context, direction, look_at);
  if (direction) return read_direction(context, *direction);
  if (!look_at)
    fail(context, attributes.block->header, "missing required attribute 'direction' or 'look-at' in @camera");
  vec3 offset = read_vec3(context, *look_at) - position;
  if (max_component(abs(offset)) == 0)
    fail(context, look_at->name, "'look-at' must differ from 'position'");
  if (!is_finite(offset)) fail(context, look_at->name, "'look-at' is too far from 'position'");
  return normalize(offset / max_component(abs(offset)));
}

// `panorama equirect|fisheye` (with `fisheye-fov DEGREES`, default 180): they see all around or
// through a circle, so they take no field of view, view plane or orthographic height.
static void set_panorama(const BuildContext& context, const Attributes& attributes, CameraDesc& camera) {
  const Attribute* panorama = find(attributes, "panorama");
  const Attribute* fisheye_fov = find(attributes, "fisheye-fov");
  if (!panorama) {
    if (fisheye_fov) fail(context, fisheye_fov->name, "'fisheye-fov' needs 'panorama fisheye'");
    return;
  }
  for (const char* other : {"fov", "view-distance", "view-size", "orthographic"}) exclusive(context, panorama, find(attributes, other));
  bool fisheye = read_choice(context, *panorama, {"equirect", "fisheye"}) == 1;
  camera.projection = fisheye ? Projection::fisheye : Projection::equirectangular;
  camera.aspect = fisheye ? 1 : 2;
  if (!fisheye_fov) return;
  if (!fisheye) fail(context, fisheye_fov->name, "'fisheye-fov' needs 'panorama fisheye'");
  camera.fisheye_fov_degrees = read_positive(context, *fisheye_fov);
  if (camera.fisheye_fov_degrees > 360)
    fail(context, fisheye_fov->arguments[0], "'fisheye-fov' must be at most 360 degrees");
}

// Field of view from `fov` or from a view plane (`view-distance` d, `view-size` w h), or the
// height of an orthographic view.
static void set_projection(const BuildContext& context, const Attributes& attributes, CameraDesc& camera) {
  const Attribute* fov = find(attributes, "fov");
  const Attribute* distance = find(attributes, "view-distance");
  const Attribute* size = find(attributes, "view-size");
  const Attribute* orthographic = find(attributes, "orthographic");
  exclusive(context, fov, distance);
  exclusive(context, fov, size);
  exclusive(context, orthographic, fov);
  exclusive(context, orthographic, distance);
  exclusive(context, orthographic, size);
  camera.vertical_fov_degrees = camera_default_fov_degrees;
  if (fov) {
    camera.vertical_fov_degrees = read_number(context, *fov);
    if (!(camera.vertical_fov_degrees > 0 && camera.vertical_fov_degrees < 180))
      fail(context, fov->arguments[0], "'fov' must be between 0 and 180 degrees, got " + shortened(fov->arguments[0].text));
  }
  if (distance || size) {
    float d = read_positive(context, require(context, attributes, "view-distance", "@camera"));
    const Attribute& plane = require(context, attributes, "view-size", "@camera");
    expect_arguments(context, plane, 2, "2 numbers (width height)");
    float width = parse_number(context, plane.arguments[0]), height = parse_number(context, plane.arguments[1]);
    if (!(width > 0 && height > 0)) fail(context, plane.name, "'view-size' must be positive");
    camera.vertical_fov_degrees = vertical_fov_from_view_plane(d, height);
    camera.aspect = width / height;
  }
  if (orthographic) {
    camera.projection = Projection::orthographic;
    camera.ortho_height = read_positive(context, *orthographic);
  }
  set_panorama(context, attributes, camera);
}

// A thin lens: `lens-radius` (0 = pinhole) focused at `focus-distance`, by default the distance
// to `look-at` along the view; `blades` 3 or more make the aperture a polygon.
static void set_lens(const BuildContext& context, const Attributes& attributes, CameraDesc& camera) {
  const Attribute* radius = find(attributes, "lens-radius");
  const Attribute* focus = find(attributes, "focus-distance");
  if (const Attribute* blades = find(attributes, "blades")) {
    camera.aperture_blades = read_integer(context, *blades, 0, 64);
    if (camera.aperture_blades == 1 || camera.aperture_blades == 2)
      fail(context, blades->arguments[0], "'blades' must be 0 (a round aperture) or 3 to 64");
  }
  if (focus) camera.focus_distance = read_positive(context, *focus);
  if (!radius) return;
  camera.lens_radius = read_non_negative(context, *radius);
  if (camera.lens_radius == 0) return;
  if (camera.projection == Projection::equirectangular || camera.projection == Projection::fisheye)
    fail(context, radius->name, "'lens-radius' needs a perspective or orthographic camera");
  if (focus) return;
  const Attribute* look_at = find(attributes, "look-at");
  if (!look_at) fail(context, radius->name, "'lens-radius' needs 'focus-distance' or 'look-at' to focus on");
  camera.focus_distance = dot(read_vec3(context, *look_at) - camera.position, camera.forward);
}

void build_camera_block(BuildContext& context, const Block& block) {
  expect_block_arguments(context, block, 1);
  Attributes attributes = index_attributes(context, block, camera_names, "@camera");
  CameraDesc camera;
  if (!block.arguments.empty()) camera.name = block.arguments[0].text;
  camera.position = read_vec3(context, require(context, attributes, "position", "@camera"));
  set_frame(context, camera, camera_forward(context, attributes, camera.position), find(attributes, "up"));
  set_projection(context, attributes, camera);
  set_lens(context, attributes, camera);
  if (const Attribute* resolution = find(attributes, "resolution")) {
    expect_arguments(context, *resolution, 2, "2 numbers (width height)");
    camera.width = parse_integer(context, resolution->arguments[0], "resolution", 1, 65536);
    camera.height = parse_integer(context, resolution->arguments[1], "resolution", 1, 65536);
  }
  context.scene.cameras.push_back(camera);
}

}  // namespace radiant::scene_format
