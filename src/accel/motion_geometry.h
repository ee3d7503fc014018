// Embree's motion blur for what moves while the shutter is open: an instance's transform and a
// mesh's vertices given at evenly spaced time steps (scene/motion_steps.h), which Embree
// interpolates at each ray's time.
#pragma once

#include <embree3/rtcore.h>

#include <vector>

#include "math/transform.h"
#include "math/vec.h"

namespace radiant {

// Gives an instance geometry one transform per time step (at least two).
void set_transform_motion(RTCGeometry instance, const std::vector<mat4>& steps);

// Gives a triangle geometry one vertex buffer per time step (at least two, each as long as the
// mesh's vertex list).
void set_vertex_motion(RTCGeometry triangles, const std::vector<std::vector<vec3>>& steps);

}  // namespace radiant
