// A loaded scene made ready to render: moved to the render space of a view, its accelerator
// built, its effects analysed. Reused for every view of `radiant batch` and `session`.
#pragma once

#include <memory>

#include "accel/scene_accel.h"
#include "materials/texture_pyramid.h"
#include "memory/memory_budget.h"
#include "render/render_options.h"
#include "render/render_space.h"
#include "render/stroke_sizing.h"
#include "scene/effects.h"

namespace radiant {

// Derived state built once per scene and reused for every view (`radiant batch`).
struct PreparedScene {
  std::unique_ptr<SceneDesc> scene;  // in render space: world positions minus `origin`
  MemoryCharge scene_memory;         // the scene's own size, when its maker handed it over (frames)
  WorldPlacement world;              // the world positions, as loaded
  dvec3 origin = {0, 0, 0};
  std::unique_ptr<SceneAccel> accel;
  AccelLayout layout = AccelLayout::single_level;  // two-level for an animation's frames
  EffectSet effects;
  double build_seconds = 0;
  StrokeSizing stroke_sizing;  // how the accelerator sized lines and points, for this view
  MemoryBudget* budget = nullptr;  // what the accelerator is charged to (RenderOptions::memory)
  MemoryCharge accel_memory;       // the accelerator's estimated size, held against the budget
  // The textures' mip-maps (charged to `budget`), when the options prepared for are trilinear.
  std::unique_ptr<TexturePyramids> texture_pyramids;
};
// Takes a loaded (world-space) scene and builds it in the render space of the view `options`
// ask for. Charges options.memory (when given) for the accelerator before building it (rebuilds
// charge the same budget) and for the textures' mip-maps when options.texture_filter is
// trilinear; throws MemoryLimitError, and std::invalid_argument for a camera that does not
// exist or a bad view.
PreparedScene prepare_scene(SceneDesc scene, const RenderOptions& options = {},
                            AccelLayout layout = AccelLayout::single_level);
// Builds the accelerator of prepared.scene anew, charging its estimated size first.
void build_accel(PreparedScene& prepared);
// Moves `prepared` to the render origin the view of `options` needs, rebuilding the accelerator
// only when that origin differs from the current one; returns the seconds spent.
double prepare_view(PreparedScene& prepared, const RenderOptions& options);
// The camera of the view `options` ask for, in world space (`framed`: the scene has none).
CameraDesc world_view_camera(const PreparedScene& prepared, const RenderOptions& options, bool& framed);
// The same from a scene's world placement and settings, before it is prepared.
CameraDesc world_view_camera(const WorldPlacement& world, const SceneSettings& settings, const RenderOptions& options,
                             bool& framed);
// The image height a render of `scene` through `camera` with `options` takes (as resolve_settings,
// in resolve_settings.cpp).
int resolved_image_height(const RenderOptions& options, const SceneDesc& scene, const CameraDesc& camera);

}  // namespace radiant
