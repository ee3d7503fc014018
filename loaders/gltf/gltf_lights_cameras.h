// KHR_lights_punctual lights and glTF cameras, placed by their node's world transform.
#pragma once

#include "gltf/gltf_context.h"

namespace radiant {

// Appends light `index` (model.lights) as seen from a node with transform `world`.
void add_light(GltfContext& context, int index, const mat4& world, const std::string& where);

// Appends camera `index`; `node_name` names it when the camera itself has no name.
void add_camera(GltfContext& context, int index, const mat4& world, const std::string& node_name,
                const std::string& where);

}  // namespace radiant
