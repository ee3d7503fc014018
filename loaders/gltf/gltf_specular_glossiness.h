// KHR_materials_pbrSpecularGlossiness, converted to the metallic-roughness model with
// KHR_materials_specular (docs/gltf-obj.md): diffuse -> base colour, specular -> the coating's
// F0, glossiness -> 1 - roughness. Approximate: the loader warns once per file.
#pragma once

#include "gltf/gltf_context.h"

namespace radiant {

constexpr const char* specular_glossiness_extension = "KHR_materials_pbrSpecularGlossiness";

// Overwrites `material`'s base colour, alpha, metallic, roughness, specular and ior from the
// extension object `spec_gloss` of the material at JSON path `where`.
void convert_specular_glossiness(GltfContext& context, const tinygltf::Value& spec_gloss, const std::string& where,
                                 MaterialDesc& material);

}  // namespace radiant
