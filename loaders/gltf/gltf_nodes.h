// The glTF node hierarchy: world transforms, and the instances, lights and cameras it places.
#pragma once

#include "gltf/gltf_context.h"

namespace radiant {

// Walks the chosen scene (options.gltf_scene, else the file's default, else scene 0) depth first
// in the order of `scene.nodes` and `children`; instances, lights and cameras appear in that order.
void convert_nodes(GltfContext& context);

// A node's local transform from `matrix` or translation/rotation/scale (glTF 2.0 section 3.5.3).
mat4 local_transform(const GltfContext& context, const tinygltf::Node& node, const std::string& where);

}  // namespace radiant
