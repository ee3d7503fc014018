#include "gltf/gltf_instancing.h"

#include <cmath>

#include "gltf/gltf_accessors.h"

namespace radiant {

namespace {

// The component types the extension allows for an attribute (with KHR_mesh_quantization's for
// TRANSLATION and SCALE); false names the accessor's type as refused.
bool allowed_component_type(const std::string& attribute, const tinygltf::Accessor& accessor) {
  int type = accessor.componentType;
  if (type == TINYGLTF_COMPONENT_TYPE_FLOAT) return true;
  bool small_integer = type == TINYGLTF_COMPONENT_TYPE_BYTE || type == TINYGLTF_COMPONENT_TYPE_SHORT ||
                       type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  if (attribute == "ROTATION")
    return accessor.normalized && (type == TINYGLTF_COMPONENT_TYPE_BYTE || type == TINYGLTF_COMPONENT_TYPE_SHORT);
  return small_integer;
}

// One attribute's values (empty when absent), its count checked against the others' (`count`,
// set by the first attribute present).
std::vector<float> read_attribute(const GltfContext& context, const tinygltf::Value& attributes,
                                  const std::string& name, int type, const std::string& where, size_t& count,
                                  bool& counted) {
  if (!attributes.Has(name)) return {};
  std::string attribute_where = where + ".attributes." + name;
  int index = index_value(context, attributes.Get(name), context.model.accessors.size(), attribute_where, "accessor");
  const tinygltf::Accessor& accessor = context.model.accessors[size_t(index)];
  if (!allowed_component_type(name, accessor))
    context.fail(attribute_where, name == "ROTATION"
                                      ? "must be FLOAT, or normalized BYTE or SHORT"
                                      : "must be FLOAT, BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT");
  if (counted && accessor.count != count)
    context.fail(attribute_where, std::to_string(accessor.count) + " elements, but the other attributes have " +
                                      std::to_string(count) + " (all must have the same count)");
  count = accessor.count, counted = true;
  int components = 0;
  std::vector<float> values = read_accessor_floats(context, index, attribute_where, {type}, components);
  for (size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      context.fail(attribute_where, "non-finite value in element " + std::to_string(i / size_t(components)));
  return values;
}

}  // namespace

GpuInstances read_gpu_instances(const GltfContext& context, const tinygltf::Value& extension, const std::string& where) {
  if (!extension.IsObject() || !extension.Has("attributes") || !extension.Get("attributes").IsObject())
    context.fail(where + ".attributes", "missing (an object naming TRANSLATION, ROTATION or SCALE accessors)");
  const tinygltf::Value& attributes = extension.Get("attributes");
  GpuInstances instances;
  bool counted = false;
  instances.translations = read_attribute(context, attributes, "TRANSLATION", TINYGLTF_TYPE_VEC3, where,
                                          instances.count, counted);
  instances.rotations = read_attribute(context, attributes, "ROTATION", TINYGLTF_TYPE_VEC4, where, instances.count,
                                       counted);
  instances.scales = read_attribute(context, attributes, "SCALE", TINYGLTF_TYPE_VEC3, where, instances.count, counted);
  if (!counted) context.fail(where + ".attributes", "names none of TRANSLATION, ROTATION and SCALE");
  for (size_t i = 0; i < instances.rotations.size(); i += 4) {
    const float* q = &instances.rotations[i];
    if (!(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3] > 0))
      context.fail(where + ".attributes.ROTATION", "element " + std::to_string(i / 4) + " is not a rotation quaternion");
  }
  return instances;
}

mat4 gpu_instance_transform(const GpuInstances& instances, size_t i) {
  vec3 t = {0, 0, 0}, s = {1, 1, 1};
  vec4 q = {0, 0, 0, 1};
  if (!instances.translations.empty()) {
    const float* v = &instances.translations[3 * i];
    t = {v[0], v[1], v[2]};
  }
  if (!instances.rotations.empty()) {
    const float* v = &instances.rotations[4 * i];
    q = {v[0], v[1], v[2], v[3]};
  }
  if (!instances.scales.empty()) {
    const float* v = &instances.scales[3 * i];
    s = {v[0], v[1], v[2]};
  }
  return compose_trs(t, q, s);  // quantized rotations are only nearly unit: normalized there
}

}  // namespace radiant
