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
    {"view-distance", ""}, {"view-size", ""}, {"resolution", ""}, {"orthographic", ""}};

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
}

void build_camera_block(BuildContext& context, const Block& block) {
  expect_block_arguments(context, block, 1);
  Attributes attributes = index_attributes(context, block, camera_names, "@camera");
  CameraDesc camera;
  if (!block.arguments.empty()) camera.name = block.arguments[0].text;
  camera.position = read_vec3(context, require(context, attributes, "position", "@camera"));
  set_frame(context, camera, camera_forward(context, attributes, camera.position), find(attributes, "up"));
  set_projection(context, attributes, camera);
  if (const Attribute* resolution = find(attributes, "resolution")) {
    expect_arguments(context, *resolution, 2, "2 numbers (width height)");
    camera.width = parse_integer(context, resolution->arguments[0], "resolution", 1, 65536);
    camera.height = parse_integer(context, resolution->arguments[1], "resolution", 1, 65536);
  }
  context.scene.cameras.push_back(camera);
}

}  // namespace radiant::scene_format
