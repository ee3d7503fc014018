// What a glTF file declares before anything is allocated: buffer sizes, external URIs, the
// extensions it requires and how many JSON values and glTF elements tinygltf will build. Read
// with a small JSON reader that keeps only those, so the memory limit and the path rules apply
// before tinygltf loads a single buffer.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace radiant {

// Stands for a data URI in GltfDeclarations (never requested as a file; maybe most of the text).
inline const std::string data_uri_marker = "data:";

struct GltfDeclarations {
  std::vector<uint64_t> buffer_byte_lengths;  // buffers[i].byteLength (0 when absent)
  std::vector<std::string> buffer_uris;       // buffers[i].uri as written ("" when absent, data_uri_marker)
  std::vector<std::string> image_uris;        // images[i].uri as written ("" when absent, data_uri_marker)
  std::vector<std::string> extensions_required;
};

// How much a document holds, counted without keeping any of it.
struct GltfJsonCounts {
  uint64_t values = 0;  // every value and member name
  // Elements of the arrays tinygltf turns into structs, by path: "materials",
  // "meshes.primitives", "extensions.KHR_lights_punctual.lights", ...
  std::map<std::string, uint64_t> elements;
};

// Checks a glTF JSON document and counts it; throws LoadError prefixed with `file`, and with the
// JSON path for an index or byte count that is not a valid integer (gltf_index_fields.h).
GltfJsonCounts count_gltf_json(const std::string& json, const std::string& file);

// Reads the declarations of a glTF JSON document; throws LoadError prefixed with `file`.
GltfDeclarations read_gltf_declarations(const std::string& json, const std::string& file);

// The JSON chunk of a GLB file; throws LoadError when the header is malformed.
std::string glb_json_chunk(const std::string& bytes, const std::string& file);

// The GLB `bytes` with its JSON chunk replaced by `json` (padded with spaces, as GLB asks), for
// the loaders that rewrite a document before tinygltf reads it.
std::string glb_with_json_chunk(const std::string& bytes, std::string json);

}  // namespace radiant
