// KHR_materials_variants: a file's named material variants (a shoe in red and in blue), one of
// which `--variant NAME` picks for the primitives that map it to a material.
#pragma once

#include "gltf/gltf_context.h"

namespace radiant {

// The names of the file's variants (the root extension's `variants[i].name`), in file order.
std::vector<std::string> variant_names(const GltfContext& context);

// The index of LoadOptions::material_variant among the file's variants, or -1 when none is asked
// for; throws LoadError when the file has no variant of that name.
int selected_variant(const GltfContext& context);

// The glTF material index of `primitive` in variant `variant` (its own material when the variant
// is -1 or the primitive has no mapping for it); mapping indices are checked.
int variant_material(const GltfContext& context, const tinygltf::Primitive& primitive, int variant,
                     const std::string& where);

}  // namespace radiant
