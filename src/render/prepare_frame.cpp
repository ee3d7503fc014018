#include "render/prepare_frame.h"

#include <chrono>
#include <utility>

#include "scene/scene_changes.h"

namespace radiant {

namespace {

bool same_point(dvec3 a, dvec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

// Updates `prepared` to `next` when only what scene_changes allows differs and the view keeps
// its render origin; false (and `prepared` untouched) otherwise.
bool update_frame(PreparedScene& prepared, SceneDesc& next, MemoryCharge& next_memory, const RenderOptions& options) {
  WorldPlacement world = record_world_placement(next);
  bool framed = false;
  dvec3 origin = choose_render_origin(world, world_view_camera(world, next.settings, options, framed).position);
  if (!same_point(origin, prepared.origin)) return false;
  place_at_render_origin(next, world, origin);
  std::optional<SceneChanges> changes = scene_changes(*prepared.scene, next);
  if (!changes) {
    place_at_render_origin(next, world, {0, 0, 0});  // back in world space, as prepare_scene takes it
    return false;
  }

  auto start = std::chrono::steady_clock::now();
  bool pyramids_kept = prepared.texture_pyramids && pyramids_serve(*prepared.scene, next);
  *prepared.scene = std::move(next);  // the accelerator and alpha masks point to this object
  prepared.scene_memory = std::move(next_memory);
  prepared.world = std::move(world);
  update_scene_accel(*prepared.accel, *changes);
  prepared.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  prepared.effects = analyze_effects(*prepared.scene);
  if (!pyramids_kept) prepared.texture_pyramids.reset();
  if (!prepared.texture_pyramids && options.texture_filter == TextureFilterMode::trilinear)
    prepared.texture_pyramids = std::make_unique<TexturePyramids>(build_texture_pyramids(*prepared.scene, options.memory));
  return true;
}

}  // namespace

FramePreparation prepare_frame(std::optional<PreparedScene>& prepared, SceneDesc next, MemoryCharge next_memory,
                               const RenderOptions& options) {
  if (prepared) {
    try {
      if (update_frame(*prepared, next, next_memory, options)) return FramePreparation::updated;
    } catch (...) {
      prepared.reset();
      throw;
    }
  }
  prepared.reset();  // gives back the previous frame's scene and accelerator before building this one
  prepared = prepare_scene(std::move(next), options, AccelLayout::two_level);
  prepared->scene_memory = std::move(next_memory);
  return FramePreparation::prepared;
}

}  // namespace radiant
