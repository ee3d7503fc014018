// Motion during the camera's shutter: values at K evenly spaced time steps, step 0 at the
// shutter's opening (ray time 0) and step K-1 at its closing (ray time 1), interpolated linearly
// between neighbouring steps exactly as Embree interpolates motion-blurred geometry.
#pragma once

#include <algorithm>
#include <vector>

#include "math/transform.h"
#include "math/vec.h"

namespace radiant {

// The most time steps one moving thing takes (each a transform, a camera pose or a copy of a
// mesh's vertices): enough for a turn of a wheel per frame, and a bound on the memory it takes.
constexpr int max_motion_steps = 16;

// A camera's pose at one time step (render space after placement, like CameraDesc's).
struct CameraPose {
  vec3 position;
  vec3 forward;  // unit
  vec3 up;       // unit
};

// Where ray time `time` in [0, 1] falls among `steps` time steps: between step `index` and the
// next, `fraction` of the way (Embree's own mapping, so hits decode where Embree found them).
struct MotionStep {
  int index = 0;
  float fraction = 0;
};
inline MotionStep motion_step(float time, int steps) {
  float scaled = std::clamp(time, 0.0f, 1.0f) * float(steps - 1);
  int index = std::clamp(int(scaled), 0, steps - 2);
  return {index, scaled - float(index)};
}

// The transform at `time` of a motion given by its per-step transforms (at least two).
inline mat4 transform_at_time(const std::vector<mat4>& steps, float time) {
  MotionStep s = motion_step(time, int(steps.size()));
  const mat4 &a = steps[size_t(s.index)], &b = steps[size_t(s.index) + 1];
  mat4 m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) m.m[r][c] = a.m[r][c] * (1 - s.fraction) + b.m[r][c] * s.fraction;
  return m;
}

// Vertex `vertex` at `time` of a mesh whose vertices move through `steps` (at least two).
inline vec3 position_at_time(const std::vector<std::vector<vec3>>& steps, uint32_t vertex, float time) {
  MotionStep s = motion_step(time, int(steps.size()));
  return lerp(steps[size_t(s.index)][vertex], steps[size_t(s.index) + 1][vertex], s.fraction);
}

// A camera's pose at `time` (at least two poses): positions linear, directions normalized after
// a linear blend, which follows a turn closely at the step counts a shutter takes.
inline CameraPose pose_at_time(const std::vector<CameraPose>& steps, float time) {
  MotionStep s = motion_step(time, int(steps.size()));
  const CameraPose &a = steps[size_t(s.index)], &b = steps[size_t(s.index) + 1];
  return {lerp(a.position, b.position, s.fraction), normalize(lerp(a.forward, b.forward, s.fraction)),
          normalize(lerp(a.up, b.up, s.fraction))};
}

}  // namespace radiant
