// `radiant render SCENE --frames A-B -o out/frame-####.png`: the frames of an animation in one
// process. The scene file is read and parsed once; each frame samples the animation into a scene
// of its own, updates the previous frame's accelerator where only what moved is rebuilt
// (render/prepare_frame.h, docs/gltf-obj.md "Many frames") and renders it with the frame's seed.
#pragma once

#include <chrono>
#include <optional>
#include <string>

#include "render/prepare_frame.h"

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

// The latest frame of an animation, prepared (its scene's budget charge included), which the
// next frame updates.
struct FrameScene {
  std::optional<PreparedScene> prepared;
  // The scene of `file` at load.animation_time, prepared from the frame before; returns how.
  FramePreparation prepare_next(SceneFile& file, const LoadOptions& load, const RenderOptions& options);
};

// Renders every frame of `animation.frames` in order and returns the exit code. An error names
// the frame it happened in; the frames written before it stay.
int render_frames(const FramesRequest& request, const AnimationFlags& animation);

}  // namespace radiant::cli
