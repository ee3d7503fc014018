// Builds small glTF documents in tests: accessors over one binary buffer, embedded as a base64
// data URI (or written beside the file, or packed as GLB).
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace radiant::test {

inline std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
    if (i + 1 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 1])) << 8;
    if (i + 2 < bytes.size()) v |= uint8_t(bytes[i + 2]);
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? table[v & 63] : '=';
  }
  return out;
}

struct GltfBuilder {
  std::string bin;
  std::vector<std::string> views, accessors;
  std::vector<std::string> more_buffers;  // JSON of buffers after the first (which holds `bin`)

  template <typename T>
  static std::string bytes_of(const std::vector<T>& values) {
    std::string out(values.size() * sizeof(T), '\0');
    if (!values.empty()) std::memcpy(out.data(), values.data(), out.size());
    return out;
  }
  // A bufferView over `bytes` (4-byte aligned); returns its index.
  int view(const std::string& bytes, int stride = 0) {
    while (bin.size() % 4) bin += '\0';
    std::string v = "{\"buffer\":0,\"byteOffset\":" + std::to_string(bin.size()) +
                    ",\"byteLength\":" + std::to_string(bytes.size());
    if (stride) v += ",\"byteStride\":" + std::to_string(stride);
    views.push_back(v + "}");
    bin += bytes;
    return int(views.size()) - 1;
  }
  // An accessor; `extra` adds JSON members (e.g. ",\"normalized\":true").
  int accessor(int view_index, int component_type, size_t count, const std::string& type,
               const std::string& extra = "") {
    std::string a = "{\"componentType\":" + std::to_string(component_type) + ",\"count\":" + std::to_string(count) +
                    ",\"type\":\"" + type + "\"";
    if (view_index >= 0) a += ",\"bufferView\":" + std::to_string(view_index);
    accessors.push_back(a + extra + "}");
    return int(accessors.size()) - 1;
  }
  int floats(const std::vector<float>& values, const std::string& type, int components) {
    return accessor(view(bytes_of(values)), 5126, values.size() / components, type);
  }
  int indices(const std::vector<uint16_t>& values) {
    return accessor(view(bytes_of(values)), 5123, values.size(), "SCALAR");
  }
  // The document: `body` holds the other top-level members, e.g. "\"meshes\":[...],\"nodes\":[...]".
  std::string gltf(const std::string& body, const std::string& buffer_uri = "") const {
    std::string uri = buffer_uri.empty() ? "data:application/octet-stream;base64," + base64(bin) : buffer_uri;
    std::string out = "{\"asset\":{\"version\":\"2.0\"}";
    if (!bin.empty()) {
      out += ",\"buffers\":[{\"byteLength\":" + std::to_string(bin.size()) + ",\"uri\":\"" + uri + "\"}" +
             later_buffers() + "]";
      out += ",\"bufferViews\":[" + join(views) + "],\"accessors\":[" + join(accessors) + "]";
    }
    return out + (body.empty() ? "" : "," + body) + "}";
  }
  // The same as a GLB: JSON chunk plus the binary chunk.
  std::string glb(const std::string& body) const {
    std::string json = "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":" + std::to_string(bin.size()) +
                       "}" + later_buffers() + "],\"bufferViews\":[" + join(views) + "],\"accessors\":[" + join(accessors) + "]," + body + "}";
    while (json.size() % 4) json += ' ';
    std::string data = bin;
    while (data.size() % 4) data += '\0';
    std::string out = "glTF";
    auto u32 = [&](uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    u32(2);
    u32(uint32_t(12 + 8 + json.size() + 8 + data.size()));
    u32(uint32_t(json.size()));
    u32(0x4E4F534A);
    out += json;
    u32(uint32_t(data.size()));
    u32(0x004E4942);
    return out + data;
  }
  std::string later_buffers() const { return more_buffers.empty() ? "" : "," + join(more_buffers); }
  static std::string join(const std::vector<std::string>& items) {
    std::string out;
    for (const auto& item : items) out += (out.empty() ? "" : ",") + item;
    return out;
  }
};

// A unit quad in the XY plane facing +Z: 4 positions, 2 triangles (accessors 0 and 1).
inline GltfBuilder quad_builder() {
  GltfBuilder b;
  b.floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3", 3);
  b.indices({0, 1, 2, 0, 2, 3});
  return b;
}

inline const char* quad_mesh = "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}]";

}  // namespace radiant::test
