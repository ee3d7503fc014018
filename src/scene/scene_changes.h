// What changed between two scenes made from one file at two animation times, as the accelerator
// sees it: which instances moved and which meshes deformed. An animation's frames differ only in
// these (and in values the accelerator does not hold), so a frame can update the previous
// frame's accelerator instead of building a new one (docs/gltf-obj.md, "Many frames").
#pragma once

#include <optional>
#include <vector>

#include "scene/scene_desc.h"

namespace radiant {

struct SceneChanges {
  std::vector<char> moved_instances;  // per instance: its transform changed
  std::vector<char> deformed_meshes;  // per mesh: its vertex positions changed
  bool shapes_changed = false;        // an analytic shape moved, turned or resized
  bool any() const;
};

// The changes from `before` to `after`, or none when the two differ in what an accelerator is
// built around: the number of meshes, instances or shapes, a mesh's triangles or vertex count, an
// instance's mesh, or which meshes have alpha-masked or single-sided materials. Values compare
// bit for bit.
std::optional<SceneChanges> scene_changes(const SceneDesc& before, const SceneDesc& after);

}  // namespace radiant
