// An animation's frames, each prepared from the one before: the scenes of two frames of one file
// differ in where instances are and how meshes are deformed, so a frame keeps the previous
// frame's accelerator and rebuilds only the geometries that changed, and keeps its texture
// mip-maps (docs/gltf-obj.md, "Many frames").
#pragma once

#include <optional>

#include "render/render.h"

namespace radiant {

// How prepare_frame came by the frame's prepared scene.
enum class FramePreparation {
  prepared,  // anew: the first frame, a scene laid out differently, or a render origin that moved
  updated,   // from the previous frame's, rebuilding only what changed
};

// Makes `prepared` the frame whose world-space scene is `next` (made from the same file as
// `prepared`'s scene), seen by the view of `options`; `next_memory`, what `next` holds against the
// budget, goes with it (the previous frame's is given back with its scene). With no previous
// frame, or one that cannot be updated, prepares it anew in the two-level layout
// (accel/scene_accel.h) that later frames update. Throws as prepare_scene does; `prepared` is
// then empty.
FramePreparation prepare_frame(std::optional<PreparedScene>& prepared, SceneDesc next, MemoryCharge next_memory,
                               const RenderOptions& options);

}  // namespace radiant
