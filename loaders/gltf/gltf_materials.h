// glTF images, textures (with samplers) and metallic-roughness materials to SceneDesc.
#pragma once

#include "gltf/gltf_context.h"

namespace radiant {

// Appends every glTF texture and material, keeping glTF indices (offset by what the scene
// already held; for glTF files that is zero), and the images the textures show
// (docs/gltf-obj.md, "Texture extensions").
void convert_textures(GltfContext& context);
void convert_materials(GltfContext& context);

// The SceneDesc material for glTF material `index` (-1 = the shared glTF default material).
int scene_material(GltfContext& context, int index, const std::string& where);

}  // namespace radiant
