// What a glTF file declares before anything is allocated: buffer sizes, external URIs and the
// extensions it requires. Read with a small JSON reader so the memory limit and the path rules
// apply before tinygltf loads a single buffer.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace radiant {

struct GltfDeclarations {
  std::vector<uint64_t> buffer_byte_lengths;  // buffers[i].byteLength (0 when absent)
  std::vector<std::string> buffer_uris;       // buffers[i].uri as written ("" when absent)
  std::vector<std::string> image_uris;        // images[i].uri as written ("" when absent)
  std::vector<std::string> extensions_required;
};

// Reads the declarations of a glTF JSON document; throws LoadError prefixed with `file`.
GltfDeclarations read_gltf_declarations(const std::string& json, const std::string& file);

// The JSON chunk of a GLB file; throws LoadError when the header is malformed.
std::string glb_json_chunk(const std::string& bytes, const std::string& file);

}  // namespace radiant
