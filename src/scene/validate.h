// Checks a SceneDesc every loader produced: indices in range, finite numbers, something to render.
#pragma once

#include "scene/scene_desc.h"

namespace radiant {

// Throws LoadError naming `scene.source_path` and the offending element, e.g.
// `scene.gltf: meshes[0].indices: index 4100 out of range (24 vertices)`.
void validate_scene(const SceneDesc& scene);

}  // namespace radiant
