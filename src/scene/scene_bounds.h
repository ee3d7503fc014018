// The bounding box of everything finite in a scene (infinite planes and tubes excluded).
#pragma once

#include "scene/scene_desc.h"

namespace radiant {

// False when the scene has no finite geometry (then lower/upper are left unchanged).
bool scene_bounds(const SceneDesc& scene, vec3& lower, vec3& upper);

}  // namespace radiant
