// The session's moves and turns (cli/session_view.h): world axes, degrees, exact digits.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "session_view.h"

using namespace radiant;
using namespace radiant::cli;

namespace {

bool near(vec3 a, vec3 b) { return length(a - b) < 1e-5f; }

SessionView looking_down_minus_z() {
  CameraDesc camera;
  camera.position = {1, 2, 3};
  camera.forward = {0, 0, -1};
  camera.up = {0, 1, 0};
  return view_of(camera);
}

}  // namespace

TEST_CASE("session view: moveto and move place the viewer, looking the same way") {
  SessionView view = looking_down_minus_z();
  move_by(view, {1, 0, -2});
  CHECK(view.position == vec3{2, 2, 1});
  move_to(view, {-5, 0, 7});
  CHECK(view.position == vec3{-5, 0, 7});
  CHECK(view.direction == vec3{0, 0, -1});
}

TEST_CASE("session view: turn rotates about the world axes in degrees, right-handed") {
  SessionView view = looking_down_minus_z();
  turn_by(view, {0, 90, 0});  // about +y: -z turns to -x (to the left when y is up)
  CHECK(near(view.direction, {-1, 0, 0}));
  CHECK(near(view.up, {0, 1, 0}));
  turn_by(view, {0, 0, 90});  // about +z: -x turns to -y, up +y to -x
  CHECK(near(view.direction, {0, -1, 0}));
  CHECK(near(view.up, {-1, 0, 0}));
  SessionView pitched = looking_down_minus_z();
  turn_by(pitched, {30, 0, 0});  // about +x: looks up by 30 degrees
  CHECK(near(pitched.direction, {0, std::sin(0.5235988f), -std::cos(0.5235988f)}));
}

TEST_CASE("session view: turnto keeps the given digits and the up side, and refuses a zero direction") {
  SessionView view = looking_down_minus_z();
  move_to(view, {300, 0, 1000});
  turn_to(view, {-300, 0, -1200});
  CameraOverride o = camera_override(view);
  CHECK(*o.look_from == vec3{300, 0, 1000});
  CHECK(*o.look_at == vec3{0, 0, -200});  // exactly the point 1237 units ahead
  CHECK(*o.up == vec3{0, 1, 0});
  turn_to(view, {0, 5, 0});  // straight up: the old up cannot stay
  CHECK(std::abs(dot(view.up, normalize(view.direction))) < 1e-6f);
  CHECK_THROWS_AS(turn_to(view, {0, 0, 0}), std::invalid_argument);
}

TEST_CASE("session view: far from the origin the look-at point is far enough ahead to keep the direction") {
  SessionView view = looking_down_minus_z();
  move_to(view, {1e7f, 0, 0});
  turn_to(view, {1, 1, 0});
  CameraOverride o = camera_override(view);
  vec3 d = *o.look_at - *o.look_from;
  CHECK(near(normalize(d), normalize(vec3{1, 1, 0})));
}
