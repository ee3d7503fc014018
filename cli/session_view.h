// The viewer of `radiant session`: where it stands and where it looks, moved and turned by the
// seed path tracer's commands. World axes and scene units throughout; angles in degrees.
#pragma once

#include "math/vec.h"
#include "render/render_options.h"
#include "scene/scene_desc.h"

namespace radiant::cli {

struct SessionView {
  vec3 position;
  // Where it looks, as given: `turnto -300 0 -1200` keeps those digits, so that the view equals
  // `--look-at` of the point that far ahead, bit for bit. Never zero.
  vec3 direction = {0, 0, -1};
  vec3 up = {0, 1, 0};  // the wanted up side; the camera makes it orthogonal to the direction
};

// The view of a scene camera (the one a render of the same settings would use).
SessionView view_of(const CameraDesc& camera);

// `moveto X Y Z`: stand at (X, Y, Z), looking the same way.
void move_to(SessionView& view, vec3 position);
// `move DX DY DZ`: step by (DX, DY, DZ) along the world axes, looking the same way.
void move_by(SessionView& view, vec3 offset);
// `turnto DX DY DZ`: look along (DX, DY, DZ), keeping the up side unless the new direction is
// parallel to it. Throws std::invalid_argument for a zero or non-finite direction.
void turn_to(SessionView& view, vec3 direction);
// `turn AX AY AZ`: rotate the view by AX degrees about the world x axis, then AY about y, then AZ
// about z (right-handed: `turn 0 10 0` turns 10 degrees to the left when y is up).
void turn_by(SessionView& view, vec3 degrees);

// The camera flags that give this view: --look-from, --look-at a point ahead (the direction
// scaled by a power of two, so no digits are lost, until it is at least as long as the position
// is far from the origin) and --up.
CameraOverride camera_override(const SessionView& view);

}  // namespace radiant::cli
