// `radiant render SCENE --frames A-B -o out/frame-####.png`: the frames of an animation in one
// process. The scene file is read and parsed once; each frame samples the animation into a scene
// of its own, builds its accelerator (rebuilt whole for every frame: docs/gltf-obj.md, "Many
// frames") and renders it with the frame's seed.
#pragma once

#include <chrono>
#include <string>

#include "animation_flags.h"
#include "load_scene.h"
#include "render_job.h"

namespace radiant::cli {

struct FramesRequest {
  std::string scene_path;
  std::string output_pattern, stats_pattern;  // with a run of '#' for the frame number ("" : no stats)
  RenderJob job;                              // every frame's settings; its outputs are replaced
  LoadOptions load;                           // with the command's budget
  std::chrono::steady_clock::time_point start;  // of the command, for the first frame's load time
};

// Renders every frame of `animation.frames` in order and returns the exit code. An error names
// the frame it happened in; the frames written before it stay.
int render_frames(const FramesRequest& request, const AnimationFlags& animation);

}  // namespace radiant::cli
