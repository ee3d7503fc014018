#include "gltf/gltf_variants.h"

namespace radiant {

namespace {

constexpr const char* variants_extension = "KHR_materials_variants";

}  // namespace

std::vector<std::string> variant_names(const GltfContext& context) {
  std::vector<std::string> names;
  auto it = context.model.extensions.find(variants_extension);
  if (it == context.model.extensions.end() || !it->second.Has("variants")) return names;
  const tinygltf::Value& variants = it->second.Get("variants");
  std::string where = std::string("extensions.") + variants_extension + ".variants";
  if (!variants.IsArray()) context.fail(where, "must be an array");
  for (size_t i = 0; i < variants.ArrayLen(); ++i) {
    const tinygltf::Value& variant = variants.Get(int(i));
    if (!variant.Has("name") || !variant.Get("name").IsString()) context.fail(element(where, i), "has no name");
    names.push_back(variant.Get("name").Get<std::string>());
  }
  return names;
}

int selected_variant(const GltfContext& context) {
  const std::string& wanted = context.options.material_variant;
  if (wanted.empty()) return -1;
  std::vector<std::string> names = variant_names(context);
  std::string known;
  for (size_t i = 0; i < names.size(); ++i) {
    if (names[i] == wanted) return int(i);
    known += (i ? ", " : "") + names[i];
  }
  throw LoadError(context.file + ": no material variant '" + wanted + "' (" +
                  (names.empty() ? std::string("the file has no KHR_materials_variants") : "variants: " + known) + ")");
}

int variant_material(const GltfContext& context, const tinygltf::Primitive& primitive, int variant,
                     const std::string& where) {
  auto it = primitive.extensions.find(variants_extension);
  if (variant < 0 || it == primitive.extensions.end() || !it->second.Has("mappings")) return primitive.material;
  const tinygltf::Value& mappings = it->second.Get("mappings");
  std::string mappings_where = where + ".extensions." + variants_extension + ".mappings";
  if (!mappings.IsArray()) context.fail(mappings_where, "must be an array");
  for (size_t m = 0; m < mappings.ArrayLen(); ++m) {
    const tinygltf::Value& mapping = mappings.Get(int(m));
    std::string mapping_where = element(mappings_where, m);
    if (!mapping.Has("variants") || !mapping.Get("variants").IsArray() || !mapping.Has("material"))
      context.fail(mapping_where, "needs a material and an array of variants");
    const tinygltf::Value& variants = mapping.Get("variants");
    for (size_t v = 0; v < variants.ArrayLen(); ++v) {
      if (!variants.Get(int(v)).IsNumber() || variants.Get(int(v)).GetNumberAsDouble() != variant) continue;
      return index_value(context, mapping.Get("material"), context.model.materials.size(), mapping_where + ".material",
                         "material");
    }
  }
  return primitive.material;
}

}  // namespace radiant
