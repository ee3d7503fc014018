// State shared by the parts of the glTF loader: the parsed model, the scene being filled, and
// the maps from glTF indices to SceneDesc indices.
#pragma once

#include <tiny_gltf.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "load_options.h"
#include "scene/scene_desc.h"

namespace radiant {

struct GltfContext {
  const tinygltf::Model& model;
  const std::string& file;  // the path as given, prefixed to every message
  const LoadOptions& options;
  SceneDesc& scene;
  std::vector<std::vector<int>> mesh_parts = {};  // glTF mesh -> its MeshDesc indices (one per primitive)
  std::vector<std::vector<StrokeDesc>> mesh_strokes = {};  // glTF mesh -> its points and lines, in object space
  std::map<int, int> mirrored_meshes = {};   // MeshDesc -> its copy with reversed winding
  int default_material = -1;                 // the glTF default material, made on first use
  int variant = -1;                          // the KHR_materials_variants index in use, or -1
  // (texture, glossinessFactor) -> the roughness texture made from its alpha (KHR_materials_pbrSpecularGlossiness)
  std::map<std::pair<int, float>, int> roughness_from_glossiness = {};

  // Throws `file: where: message`.
  [[noreturn]] void fail(const std::string& where, const std::string& message) const {
    throw LoadError(file + ": " + where + ": " + message);
  }
  void warn(const std::string& message) { scene.warnings.push_back(file + ": " + message); }
  // Charges the load's memory budget before `bytes` are allocated for `where`; every read is
  // charged, since a hostile file may read one big accessor from many primitives.
  void charge(uint64_t bytes, const std::string& where) const { charge_load(options, bytes, file + ": " + where); }
};

// "name[index]", the JSON path of an array element.
inline std::string element(const std::string& name, size_t index) {
  return name + "[" + std::to_string(index) + "]";
}

// "meshes", "nodes": the plural of an element name, for messages.
inline std::string plural(const std::string& what) { return what + (what.back() == 'h' ? "es" : "s"); }

// Checks that `index` points into an array of `size` elements.
inline void check_index(const GltfContext& context, int index, size_t size, const std::string& where,
                        const std::string& what) {
  if (index < 0 || size_t(index) >= size)
    context.fail(where, what + " " + std::to_string(index) + " out of range (" + std::to_string(size) +
                            " " + plural(what) + ")");
}

// A number from the file as messages show it: "1e+10", "-0.5", "3".
inline std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// A radiance or intensity from the file as a float: it must be a non-negative number a float holds.
inline float non_negative_float(const GltfContext& context, double value, const std::string& where) {
  if (value < 0) context.fail(where, "must not be negative, got " + number_text(value));
  if (!(value <= std::numeric_limits<float>::max())) context.fail(where, number_text(value) + " does not fit in a float");
  return float(value);
}

// An index that tinygltf leaves as a JSON value (extensions): a whole number inside an array of
// `size` elements, checked before it becomes an int (a double out of int's range is undefined
// behaviour to convert).
inline int index_value(const GltfContext& context, const tinygltf::Value& value, size_t size,
                       const std::string& where, const std::string& what) {
  if (!value.IsNumber()) context.fail(where, "expected a " + what + " index, found a non-number");
  double index = value.GetNumberAsDouble();
  if (index != std::floor(index)) context.fail(where, what + " " + number_text(index) + " is not a whole number");
  if (!(index >= 0 && index < double(size)))
    context.fail(where, what + " " + number_text(index) + " out of range (" + std::to_string(size) + " " +
                            plural(what) + ")");
  return int(index);
}

}  // namespace radiant
