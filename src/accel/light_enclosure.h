// A diagnostic for `radiant info`: point and spot lights shut inside closed geometry.
#pragma once

#include <string>
#include <vector>

#include "scene/scene_desc.h"

namespace radiant {

// One warning per point or spot light enclosed by geometry, found by casting rays from the light.
std::vector<std::string> enclosed_light_warnings(const SceneDesc& scene);

}  // namespace radiant
