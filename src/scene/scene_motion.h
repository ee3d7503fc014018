// What moves while the shutter is open: the questions the effect analysis, validation and
// `radiant info` ask of a SceneDesc's motion steps (scene/motion_steps.h).
#pragma once

#include <cstddef>
#include <string>

#include "scene/scene_desc.h"

namespace radiant {

struct MotionCounts {
  size_t instances = 0, meshes = 0, cameras = 0;  // how many of each carry motion steps
  size_t any() const { return instances + meshes + cameras; }
};
MotionCounts count_motion(const SceneDesc& scene);

// "2 moving instance(s), 1 deforming mesh(es)...": the reason `info` gives for motion blur.
std::string describe_motion(const MotionCounts& counts);

// Gives `scene` the motion steps of what differs among `steps` (the same scene posed at evenly
// spaced times across the shutter, 2 to max_motion_steps of them): instance transforms, mesh
// vertices, camera poses. False, and nothing added, when a step is not the same scene posed
// differently (another number of instances, meshes, cameras or vertices).
bool add_motion_steps(SceneDesc& scene, const std::vector<SceneDesc>& steps);

// Drops every motion step: the scene as the rendered time shows it (--effects -motion-blur).
void drop_motion(SceneDesc& scene);

}  // namespace radiant
