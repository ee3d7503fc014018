// Loader of Wavefront OBJ/MTL through tinyobjloader.
#pragma once

#include <string>

#include "load_options.h"
#include "scene/scene_desc.h"

namespace radiant {

// Appends the meshes, materials and textures of `path` to `scene`, placed by `transform`.
// `material_override` >= 0 replaces every material of the file. Throws LoadError.
void append_obj(SceneDesc& scene, const std::string& path, const mat4& transform,
                const LoadOptions& options, int material_override = -1);

// A scene holding just the OBJ file (no camera, no lights).
SceneDesc load_obj(const std::string& path, const LoadOptions& options);

}  // namespace radiant
