// Loader of glTF 2.0 (.gltf with external or data-URI buffers, and .glb) through tinygltf.
#pragma once

#include <string>

#include "load_scene.h"

namespace radiant {

// Throws LoadError naming the file and the JSON path of the problem.
SceneDesc load_gltf(const std::string& path, const LoadOptions& options);

}  // namespace radiant
