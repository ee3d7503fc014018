#include "gltf/gltf_accessors.h"

#include <algorithm>
#include <cstring>

namespace radiant {

namespace {

std::string type_name(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "type " + std::to_string(type);
  }
}

std::string component_type_name(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
    default: return "component type " + std::to_string(type);
  }
}

size_t component_size(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

template <typename T>
T load(const unsigned char* p) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  return v;
}

// One component; normalized integers follow the glTF 2.0 specification, section 3.11.
float component_value(const unsigned char* p, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      float v = load<int8_t>(p);
      return normalized ? std::max(v / 127.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? load<uint8_t>(p) / 255.0f : load<uint8_t>(p);
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      float v = load<int16_t>(p);
      return normalized ? std::max(v / 32767.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return normalized ? load<uint16_t>(p) / 65535.0f : load<uint16_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return float(load<uint32_t>(p));
    default: return load<float>(p);
  }
}

// Where `count` elements of `element_size` bytes, `stride` apart, start in the buffer, after checking
// they lie inside bufferView `view_index` and its buffer.
const unsigned char* checked_view_data(const GltfContext& context, int view_index, size_t byte_offset,
                                       size_t count, size_t element_size, size_t stride,
                                       const std::string& where, const std::string& what) {
  const auto& model = context.model;
  check_index(context, view_index, model.bufferViews.size(), where, "bufferView");
  const tinygltf::BufferView& view = model.bufferViews[view_index];
  std::string view_name = element("bufferViews", size_t(view_index));
  check_index(context, view.buffer, model.buffers.size(), where + " (" + view_name + ")", "buffer");
  size_t buffer_size = model.buffers[view.buffer].data.size();
  if (view.byteLength > buffer_size || view.byteOffset > buffer_size - view.byteLength)
    context.fail(where, view_name + " runs past the end of " + element("buffers", size_t(view.buffer)) +
                            " (" + std::to_string(buffer_size) + " bytes)");
  if (count == 0) return nullptr;
  unsigned __int128 end = (unsigned __int128)stride * (count - 1) + element_size + byte_offset;
  if (end > view.byteLength)
    context.fail(where, what + " runs past the end of " + view_name + " (" + std::to_string(view.byteLength) +
                            " bytes)");
  return model.buffers[view.buffer].data.data() + view.byteOffset + byte_offset;
}

const tinygltf::Accessor& checked_accessor(const GltfContext& context, int index, const std::string& where) {
  check_index(context, index, context.model.accessors.size(), where, "accessor");
  return context.model.accessors[index];
}

// Overwrites the elements a sparse accessor lists (glTF 2.0 section 3.6.2.3).
void apply_sparse(const GltfContext& context, const tinygltf::Accessor& accessor, int components,
                  std::vector<float>& out, const std::string& where) {
  const auto& sparse = accessor.sparse;
  std::string what = where + " (sparse)";
  if (sparse.count <= 0 || size_t(sparse.count) > accessor.count)
    context.fail(what, "sparse count " + std::to_string(sparse.count) + " out of range (" +
                           std::to_string(accessor.count) + " elements)");
  size_t index_size = component_size(sparse.indices.componentType);
  if (index_size == 0 || sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
      sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_SHORT ||
      sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT)
    context.fail(what, "sparse indices must be unsigned integers, found " +
                           component_type_name(sparse.indices.componentType));
  if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0) context.fail(what, "negative byteOffset");
  size_t value_size = component_size(accessor.componentType) * components;
  const unsigned char* indices = checked_view_data(context, sparse.indices.bufferView, sparse.indices.byteOffset,
                                                   sparse.count, index_size, index_size, what, "sparse indices");
  const unsigned char* values = checked_view_data(context, sparse.values.bufferView, sparse.values.byteOffset,
                                                  sparse.count, value_size, value_size, what, "sparse values");
  for (int i = 0; i < sparse.count; ++i) {
    size_t target = size_t(component_value(indices + i * index_size, sparse.indices.componentType, false));
    if (target >= accessor.count)
      context.fail(what, "sparse index " + std::to_string(target) + " out of range (" +
                             std::to_string(accessor.count) + " elements)");
    for (int c = 0; c < components; ++c)
      out[target * components + c] = component_value(values + i * value_size + c * component_size(accessor.componentType),
                                                      accessor.componentType, accessor.normalized);
  }
}

std::vector<float> read_elements(const GltfContext& context, const tinygltf::Accessor& accessor, int components,
                                 const std::string& where) {
  size_t size = component_size(accessor.componentType);
  if (size == 0) context.fail(where, "unsupported " + component_type_name(accessor.componentType));
  context.charge(saturating_multiply(accessor.count, sizeof(float) * components), where);
  std::vector<float> out(accessor.count * components, 0.0f);
  if (accessor.bufferView >= 0) {
    size_t element_size = size * components;
    size_t stride = element_size;
    if (size_t(accessor.bufferView) < context.model.bufferViews.size() &&
        context.model.bufferViews[accessor.bufferView].byteStride != 0)
      stride = context.model.bufferViews[accessor.bufferView].byteStride;
    if (stride < element_size)
      context.fail(where, "byteStride " + std::to_string(stride) + " is smaller than the element size " +
                              std::to_string(element_size));
    const unsigned char* data = checked_view_data(context, accessor.bufferView, accessor.byteOffset,
                                                  accessor.count, element_size, stride, where, "accessor");
    for (size_t i = 0; i < accessor.count; ++i)
      for (int c = 0; c < components; ++c)
        out[i * components + c] = component_value(data + i * stride + c * size, accessor.componentType,
                                                  accessor.normalized);
  }
  if (accessor.sparse.isSparse) apply_sparse(context, accessor, components, out, where);
  return out;
}

}  // namespace

const unsigned char* buffer_view_bytes(const GltfContext& context, int view_index, const std::string& where,
                                       size_t& length) {
  check_index(context, view_index, context.model.bufferViews.size(), where, "bufferView");
  length = context.model.bufferViews[size_t(view_index)].byteLength;
  return checked_view_data(context, view_index, 0, 1, length, 0, where, "the data");
}

size_t accessor_count(const GltfContext& context, int index, const std::string& where) {
  return checked_accessor(context, index, where).count;
}

std::vector<float> read_accessor_floats(const GltfContext& context, int index, const std::string& where,
                                        const std::vector<int>& types, int& components) {
  const tinygltf::Accessor& accessor = checked_accessor(context, index, where);
  if (std::find(types.begin(), types.end(), accessor.type) == types.end()) {
    std::string expected;
    for (int type : types) expected += (expected.empty() ? "" : " or ") + type_name(type);
    context.fail(where, "expected " + expected + ", found " + type_name(accessor.type));
  }
  components = tinygltf::GetNumComponentsInType(uint32_t(accessor.type));
  return read_elements(context, accessor, components, where);
}

std::vector<uint32_t> read_accessor_indices(const GltfContext& context, int index, const std::string& where) {
  const tinygltf::Accessor& accessor = checked_accessor(context, index, where);
  if (accessor.type != TINYGLTF_TYPE_SCALAR)
    context.fail(where, "expected SCALAR, found " + type_name(accessor.type));
  int type = accessor.componentType;
  if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    context.fail(where, "indices must be unsigned integers, found " + component_type_name(type));
  tinygltf::Accessor raw = accessor;
  raw.normalized = false;  // indices are integers whatever the flag says
  std::vector<float> values = read_elements(context, raw, 1, where);
  context.charge(values.size() * sizeof(uint32_t), where);
  std::vector<uint32_t> out(values.size());
  // Unsigned ints above 2^24 lose precision in float; read them exactly instead.
  if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT && !accessor.sparse.isSparse && accessor.bufferView >= 0) {
    const auto& view = context.model.bufferViews[accessor.bufferView];
    size_t stride = view.byteStride ? view.byteStride : 4;
    const unsigned char* data = context.model.buffers[view.buffer].data.data() + view.byteOffset + accessor.byteOffset;
    for (size_t i = 0; i < out.size(); ++i) out[i] = load<uint32_t>(data + i * stride);
    return out;
  }
  for (size_t i = 0; i < out.size(); ++i) out[i] = uint32_t(values[i]);
  return out;
}

}  // namespace radiant
