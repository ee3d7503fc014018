#include "gltf/gltf_meshopt.h"

#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

#include <cmath>

#include "message_text.h"

namespace radiant {

namespace {

// What a placeholder buffer becomes for tinygltf: one byte, since it refuses an empty data URI.
constexpr const char* placeholder_uri = "data:application/octet-stream;base64,AA==";

// A compressed bufferView's extension object, as read and checked.
struct CompressedView {
  int buffer = 0;
  uint64_t byte_offset = 0, byte_length = 0, byte_stride = 0, count = 0;
  std::string mode, filter;
};

// A whole, non-negative number member of the extension object (`fallback` when absent and
// `required` is false); a double beyond 2^53 cannot be a size a file holds.
uint64_t size_member(const GltfContext& context, const tinygltf::Value& object, const std::string& name,
                     const std::string& at, bool required, uint64_t fallback = 0) {
  if (!object.Has(name)) {
    if (required) context.fail(at, "missing required member " + name);
    return fallback;
  }
  const tinygltf::Value& value = object.Get(name);
  double number = value.IsNumber() ? value.GetNumberAsDouble() : -1;
  if (!(number >= 0 && number <= 9007199254740992.0) || number != std::floor(number))
    context.fail(at + "." + name, "expected a whole number of at least 0");
  return uint64_t(number);
}

std::string string_member(const GltfContext& context, const tinygltf::Value& object, const std::string& name,
                          const std::string& at, const std::string& fallback) {
  if (!object.Has(name)) {
    if (fallback.empty()) context.fail(at, "missing required member " + name);
    return fallback;
  }
  const tinygltf::Value& value = object.Get(name);
  if (!value.IsString()) context.fail(at + "." + name, "expected a string");
  return value.Get<std::string>();
}

// The extension object of bufferView `view`, checked against the rules of the extension's
// specification (which are also what the decoders assume).
CompressedView read_compressed_view(const GltfContext& context, const tinygltf::BufferView& view,
                                    const tinygltf::Value& extension, const std::string& at) {
  if (!extension.IsObject()) context.fail(at, "expected an object");
  CompressedView c;
  if (!extension.Has("buffer")) context.fail(at, "missing required member buffer");
  c.buffer = index_value(context, extension.Get("buffer"), context.model.buffers.size(), at + ".buffer", "buffer");
  c.byte_offset = size_member(context, extension, "byteOffset", at, false);
  c.byte_length = size_member(context, extension, "byteLength", at, true);
  c.byte_stride = size_member(context, extension, "byteStride", at, true);
  c.count = size_member(context, extension, "count", at, true);
  c.mode = string_member(context, extension, "mode", at, "");
  c.filter = string_member(context, extension, "filter", at, "NONE");
  std::string stride = std::to_string(c.byte_stride);
  if (c.mode == "ATTRIBUTES") {
    if (c.byte_stride == 0 || c.byte_stride > 256 || c.byte_stride % 4)
      context.fail(at + ".byteStride", "ATTRIBUTES needs a multiple of 4 up to 256, found " + stride);
  } else if (c.mode == "TRIANGLES" || c.mode == "INDICES") {
    if (c.byte_stride != 2 && c.byte_stride != 4) context.fail(at + ".byteStride", c.mode + " needs 2 or 4, found " + stride);
    if (c.filter != "NONE") context.fail(at + ".filter", c.mode + " takes no filter, found " + c.filter);
    if (c.mode == "TRIANGLES" && c.count % 3)
      context.fail(at + ".count", "TRIANGLES needs a multiple of 3, found " + std::to_string(c.count));
  } else {
    context.fail(at + ".mode", "expected ATTRIBUTES, TRIANGLES or INDICES, found '" + escaped(c.mode) + "'");
  }
  if (c.filter != "NONE" && c.filter != "OCTAHEDRAL" && c.filter != "QUATERNION" && c.filter != "EXPONENTIAL")
    context.fail(at + ".filter", "expected NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL, found '" + escaped(c.filter) + "'");
  bool stride_fits = c.filter == "OCTAHEDRAL"    ? c.byte_stride == 4 || c.byte_stride == 8
                     : c.filter == "QUATERNION"  ? c.byte_stride == 8
                     : c.filter == "EXPONENTIAL" ? c.byte_stride % 4 == 0
                                                 : true;
  if (!stride_fits) context.fail(at + ".filter", c.filter + " does not take a byteStride of " + stride);
  if (view.byteStride != 0 && view.byteStride != c.byte_stride)
    context.fail(at + ".byteStride", stride + " differs from the bufferView's byteStride " + std::to_string(view.byteStride));
  if (saturating_multiply(c.count, c.byte_stride) != view.byteLength)
    context.fail(at, "count × byteStride is " + std::to_string(c.count) + " × " + stride +
                         ", but the bufferView's byteLength is " + std::to_string(view.byteLength));
  const std::vector<unsigned char>& source = context.model.buffers[size_t(c.buffer)].data;
  if (c.byte_offset > source.size() || c.byte_length > source.size() - c.byte_offset)
    context.fail(at, "the compressed bytes " + std::to_string(c.byte_offset) + ".." +
                         std::to_string(saturating_add(c.byte_offset, c.byte_length)) + " lie beyond " +
                         element("buffers", size_t(c.buffer)) + " (" + std::to_string(source.size()) + " bytes)");
  return c;
}

// Decodes `c` into `out` (count × byteStride bytes) and applies its filter; 0 on success, else
// the decoder's error code.
int decode(const CompressedView& c, const unsigned char* data, std::vector<unsigned char>& out) {
  size_t count = size_t(c.count), stride = size_t(c.byte_stride), length = size_t(c.byte_length);
  if (c.mode == "TRIANGLES") return meshopt_decodeIndexBuffer(out.data(), count, stride, data, length);
  if (c.mode == "INDICES") return meshopt_decodeIndexSequence(out.data(), count, stride, data, length);
  if (int error = meshopt_decodeVertexBuffer(out.data(), count, stride, data, length)) return error;
  if (c.filter == "OCTAHEDRAL") meshopt_decodeFilterOct(out.data(), count, stride);
  if (c.filter == "QUATERNION") meshopt_decodeFilterQuat(out.data(), count, stride);
  if (c.filter == "EXPONENTIAL") meshopt_decodeFilterExp(out.data(), count, stride);
  return 0;
}

}  // namespace

bool is_meshopt_placeholder(const GltfDeclarations& declared, size_t index, bool binary) {
  return index < declared.buffer_uris.size() && declared.buffer_uris[index].empty() && (!binary || index > 0);
}

bool with_meshopt_placeholders(const std::string& file_bytes, bool binary, const GltfDeclarations& declared,
                               std::string& rewritten) {
  std::string json = binary ? glb_json_chunk(file_bytes, "") : file_bytes;
  if (json.find(meshopt_extension) == std::string::npos) return false;
  nlohmann::json document = nlohmann::json::parse(json, nullptr, false);
  if (document.is_discarded() || !document.contains("buffers") || !document["buffers"].is_array()) return false;
  nlohmann::json& buffers = document["buffers"];
  bool changed = false;
  for (size_t i = 0; i < buffers.size(); ++i) {
    if (!buffers[i].is_object() || !is_meshopt_placeholder(declared, i, binary)) continue;
    buffers[i]["uri"] = placeholder_uri;
    buffers[i]["byteLength"] = 1;
    changed = true;
  }
  if (!changed) return false;
  rewritten = binary ? glb_with_json_chunk(file_bytes, document.dump()) : document.dump();
  return true;
}

void decode_meshopt_views(tinygltf::Model& model, GltfContext& context) {
  for (size_t v = 0; v < model.bufferViews.size(); ++v) {
    auto found = model.bufferViews[v].extensions.find(meshopt_extension);
    if (found == model.bufferViews[v].extensions.end()) continue;
    std::string at = element("bufferViews", v) + ".extensions." + meshopt_extension;
    CompressedView c = read_compressed_view(context, model.bufferViews[v], found->second, at);
    uint64_t decoded_bytes = c.count * c.byte_stride;  // equals the view's byteLength, checked
    context.charge(decoded_bytes, at + ": decoding " + std::to_string(c.count) + " elements of " +
                                      std::to_string(c.byte_stride) + " bytes");
    std::vector<unsigned char> decoded(static_cast<size_t>(decoded_bytes));
    const unsigned char* data = model.buffers[size_t(c.buffer)].data.data() + c.byte_offset;
    if (int error = decode(c, data, decoded))
      context.fail(at, "cannot decode the " + c.mode + " data: it is malformed or truncated (meshoptimizer error " +
                           std::to_string(error) + ")");
    tinygltf::Buffer buffer;
    buffer.data = std::move(decoded);
    model.buffers.push_back(std::move(buffer));
    tinygltf::BufferView& view = model.bufferViews[v];
    view.buffer = int(model.buffers.size() - 1);
    view.byteOffset = 0;
    view.extensions.erase(meshopt_extension);
  }
}

}  // namespace radiant
