#include "gltf/gltf_draco.h"

#include <draco/compression/decode.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>
#include <limits>

#include "gltf/gltf_accessors.h"
#include "gltf/gltf_declarations.h"
#include "scene/scene_memory.h"

namespace radiant {

namespace {

constexpr const char* draco_extension = "KHR_draco_mesh_compression";

// Bytes the decoder holds besides its output: its own copy of every attribute with the values of
// its prediction schemes (about three copies), the corner table of the connectivity (about 64
// bytes per face) and a point-to-value map per attribute.
uint64_t draco_decoder_bytes(uint64_t attribute_bytes, uint64_t faces, uint64_t points, uint64_t attributes) {
  return saturating_add(saturating_add(saturating_multiply(attribute_bytes, 3), saturating_multiply(faces, 64)),
                        saturating_multiply(saturating_multiply(points, attributes), 4));
}

// Reads a Draco stream's header fields (bitstream specification 2.2) up to the triangle count.
struct DracoHeaderReader {
  const unsigned char* data;
  size_t length, at = 0;
  bool ok = true;
  unsigned byte() {
    if (at >= length) return ok = false, 0;
    return data[at++];
  }
  uint64_t varint() {  // LEB128, at most five bytes for a 32-bit value
    uint64_t value = 0;
    for (int shift = 0; shift < 35; shift += 7) {
      unsigned b = byte();
      value |= uint64_t(b & 0x7F) << shift;
      if (!(b & 0x80)) return value;
    }
    return ok = false, 0;
  }
  void skip(uint64_t bytes) {
    if (bytes > length - std::min(at, length)) ok = false;
    else at += bytes;
  }
  // A metadata element: its entries, then its sub-elements (nested at most `depth` deep).
  void skip_metadata(int depth) {
    if (depth > 32) return void(ok = false);
    for (uint64_t entries = varint(); ok && entries > 0; --entries) skip(byte()), skip(byte());
    for (uint64_t subs = varint(); ok && subs > 0; --subs) skip(byte()), skip_metadata(depth + 1);
  }
};

// The counts a Draco mesh stream declares, which the decoder allocates by.
struct DracoCounts {
  uint64_t triangles = 0;
  uint64_t vertices = 0;  // sequential: its points; edgebreaker: its encoded vertices
};

// Reads a Draco mesh stream's header up to its counts, before decoding; "" on success, else the
// reason it cannot be read.
std::string declared_counts(const unsigned char* data, size_t length, DracoCounts& counts) {
  DracoHeaderReader r{data, length};
  if (length < 11 || std::memcmp(data, "DRACO", 5) != 0) return "not a Draco stream";
  r.at = 5;
  unsigned major = r.byte(), minor = r.byte(), encoder_type = r.byte(), method = r.byte();
  unsigned flags_low = r.byte(), flags_high = r.byte();  // little-endian UI16
  unsigned flags = flags_low | (flags_high << 8);
  if (major != 2 || minor != 2)
    return "Draco bitstream version " + std::to_string(major) + "." + std::to_string(minor) + " (only 2.2 is read)";
  if (encoder_type != 1) return "not a triangle mesh (a point cloud)";
  if (flags & 0x8000) {  // metadata: per-attribute elements, then the file's
    for (uint64_t count = r.varint(); r.ok && count > 0; --count) r.varint(), r.skip_metadata(0);
    r.skip_metadata(0);
  }
  if (method == 1) {  // edgebreaker: traversal type, encoded vertices, faces
    r.byte();
    counts.vertices = r.varint();
    counts.triangles = r.varint();
  } else if (method == 0) {  // sequential: faces, points
    counts.triangles = r.varint();
    counts.vertices = r.varint();
  } else {
    return "unknown Draco encoding method " + std::to_string(method);
  }
  return r.ok ? "" : "the Draco header ends early";
}

// Appends `bytes` to `buffer` as a new bufferView and returns its index.
int append_view(tinygltf::Model& model, int buffer, const void* bytes, size_t size) {
  std::vector<unsigned char>& data = model.buffers[size_t(buffer)].data;
  tinygltf::BufferView view;
  view.buffer = buffer;
  view.byteOffset = data.size();
  view.byteLength = size;
  const auto* begin = static_cast<const unsigned char*>(bytes);
  data.insert(data.end(), begin, begin + size);
  model.bufferViews.push_back(view);
  return int(model.bufferViews.size() - 1);
}

// Points accessor `index` at plain values in bufferView `view`.
void point_accessor_at(tinygltf::Accessor& accessor, int view, int component_type) {
  accessor.bufferView = view;
  accessor.byteOffset = 0;
  accessor.componentType = component_type;
  accessor.normalized = false;
  accessor.sparse.isSparse = false;
}

// One attribute of the decoded mesh as floats, `components` per point, in point order.
std::vector<float> decoded_floats(const GltfContext& context, const draco::Mesh& mesh, const draco::PointAttribute& attribute,
                                  int components, const std::string& where) {
  if (attribute.num_components() != components)
    context.fail(where, "the compressed attribute has " + std::to_string(attribute.num_components()) +
                            " components, the accessor " + std::to_string(components));
  std::vector<float> values(size_t(mesh.num_points()) * size_t(components));
  for (uint32_t point = 0; point < mesh.num_points(); ++point)
    if (!attribute.ConvertValue<float>(attribute.mapped_index(draco::PointIndex(point)), int8_t(components),
                                       &values[size_t(point) * components]))
      context.fail(where, "the compressed attribute cannot be read as numbers");
  return values;
}

void decode_primitive(tinygltf::Model& model, GltfContext& context, tinygltf::Primitive& primitive,
                      const std::string& where) {
  std::string at = where + ".extensions." + draco_extension;
  const tinygltf::Value& extension = primitive.extensions.at(draco_extension);
  if (!extension.IsObject()) context.fail(at, "expected an object");
  int view = index_value(context, extension.Get("bufferView"), model.bufferViews.size(), at + ".bufferView", "bufferView");
  const tinygltf::Value& ids = extension.Get("attributes");
  if (!ids.IsObject()) context.fail(at + ".attributes", "expected an object");
  if (primitive.indices < 0) context.fail(where, "a compressed primitive needs its indices accessor");
  if (!primitive.attributes.count("POSITION")) context.fail(where + ".attributes", "no POSITION attribute");
  uint64_t points = accessor_count(context, primitive.attributes.at("POSITION"), where + ".attributes.POSITION");
  uint64_t corners = accessor_count(context, primitive.indices, where + ".indices");
  uint64_t point_bytes = 0;  // the decoded floats of one point, all attributes
  for (const std::string& name : ids.Keys()) {
    auto found = primitive.attributes.find(name);
    if (found == primitive.attributes.end())
      context.fail(at + ".attributes." + name, "not among the primitive's attributes");
    accessor_count(context, found->second, where + ".attributes." + name);  // checks the index
    const tinygltf::Accessor& accessor = model.accessors[size_t(found->second)];
    point_bytes += uint64_t(std::max(0, tinygltf::GetNumComponentsInType(uint32_t(accessor.type)))) * 4;
  }
  size_t length = 0;
  const unsigned char* data = buffer_view_bytes(context, view, at + ".bufferView", length);
  DracoCounts declared;
  std::string unreadable = declared_counts(data, length, declared);
  if (!unreadable.empty()) context.fail(at, unreadable);
  if (declared.triangles * 3 != corners)
    context.fail(at, "declares " + std::to_string(declared.triangles) + " triangles, but the indices accessor has " +
                         std::to_string(corners) + " indices");
  // Charged before the decoder allocates: the output by the accessors' counts, the decoder's own
  // copy by the larger of those and the vertex count the header declares (a stream decoding to
  // other counts than the accessors' is refused after).
  uint64_t decoder_points = std::max(points, declared.vertices);
  uint64_t output_bytes = saturating_add(saturating_multiply(points, point_bytes), saturating_multiply(corners, 4));
  uint64_t decoder_bytes =
      draco_decoder_bytes(saturating_multiply(decoder_points, point_bytes), corners / 3, decoder_points, ids.Keys().size());
  context.charge(saturating_add(output_bytes, decoder_bytes),
                 at + ": decoding " + std::to_string(decoder_points) + " points and " + std::to_string(corners / 3) +
                     " triangles");
  draco::DecoderBuffer buffer;
  buffer.Init(reinterpret_cast<const char*>(data), length);
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok()) context.fail(at, "cannot decode: " + decoded.status().error_msg_string());
  std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
  if (mesh->num_points() != points)
    context.fail(at, "decodes to " + std::to_string(mesh->num_points()) + " points, but POSITION has " +
                         std::to_string(points));
  if (uint64_t(mesh->num_faces()) * 3 != corners)
    context.fail(at, "decodes to " + std::to_string(mesh->num_faces()) + " triangles, but the indices accessor has " +
                         std::to_string(corners) + " indices");

  model.buffers.emplace_back();
  int target = int(model.buffers.size() - 1);
  model.buffers.back().data.reserve(output_bytes);
  for (const std::string& name : ids.Keys()) {
    std::string attribute_at = at + ".attributes." + name;
    int id = index_value(context, ids.Get(name), std::numeric_limits<int>::max(), attribute_at, "attribute id");
    const draco::PointAttribute* attribute = mesh->GetAttributeByUniqueId(uint32_t(id));
    if (!attribute) context.fail(attribute_at, "no compressed attribute with id " + std::to_string(id));
    tinygltf::Accessor& accessor = model.accessors[size_t(primitive.attributes.at(name))];
    std::vector<float> values = decoded_floats(context, *mesh, *attribute,
                                               tinygltf::GetNumComponentsInType(uint32_t(accessor.type)), attribute_at);
    point_accessor_at(accessor, append_view(model, target, values.data(), values.size() * sizeof(float)),
                      TINYGLTF_COMPONENT_TYPE_FLOAT);
  }
  std::vector<uint32_t> indices(corners);
  for (uint32_t face = 0; face < mesh->num_faces(); ++face)
    for (int corner = 0; corner < 3; ++corner) indices[size_t(face) * 3 + corner] = mesh->face(draco::FaceIndex(face))[corner].value();
  tinygltf::Accessor& index_accessor = model.accessors[size_t(primitive.indices)];
  point_accessor_at(index_accessor, append_view(model, target, indices.data(), indices.size() * sizeof(uint32_t)),
                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  index_accessor.type = TINYGLTF_TYPE_SCALAR;
  primitive.extensions.erase(draco_extension);
}

}  // namespace

bool with_draco_index_views(const std::string& file_bytes, bool binary, std::string& rewritten) {
  std::string json = binary ? glb_json_chunk(file_bytes, "") : file_bytes;
  if (json.find(draco_extension) == std::string::npos) return false;
  nlohmann::json document = nlohmann::json::parse(json, nullptr, false);
  if (document.is_discarded() || !document.contains("meshes") || !document.contains("accessors")) return false;
  nlohmann::json& accessors = document["accessors"];
  bool changed = false;
  for (nlohmann::json& mesh : document["meshes"]) {
    if (!mesh.is_object() || !mesh.contains("primitives")) continue;
    for (nlohmann::json& primitive : mesh["primitives"]) {
      if (!primitive.is_object() || !primitive.contains("indices") || !primitive["indices"].is_number_unsigned() ||
          !primitive.contains("extensions") || !primitive["extensions"].contains(draco_extension))
        continue;
      const nlohmann::json& extension = primitive["extensions"][draco_extension];
      size_t index = primitive["indices"].get<size_t>();
      if (!extension.is_object() || !extension.contains("bufferView") || index >= accessors.size()) continue;
      nlohmann::json& accessor = accessors[index];
      if (!accessor.is_object() || accessor.contains("bufferView")) continue;
      accessor["bufferView"] = extension["bufferView"];
      changed = true;
    }
  }
  if (!changed) return false;
  rewritten = binary ? glb_with_json_chunk(file_bytes, document.dump()) : document.dump();
  return true;
}

void decode_draco_primitives(tinygltf::Model& model, GltfContext& context) {
  for (size_t m = 0; m < model.meshes.size(); ++m)
    for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
      tinygltf::Primitive& primitive = model.meshes[m].primitives[p];
      // Points and lines are skipped later with a warning, compressed or not.
      if (!primitive.extensions.count(draco_extension) || primitive.mode <= TINYGLTF_MODE_LINE_STRIP) continue;
      std::string where = element("meshes", m) + "." + element("primitives", p);
      if (primitive.mode != TINYGLTF_MODE_TRIANGLES)
        context.fail(where + ".mode", std::string(draco_extension) + " is read for TRIANGLES only, found mode " +
                                          std::to_string(primitive.mode));
      decode_primitive(model, context, primitive, where);
    }
}

}  // namespace radiant
