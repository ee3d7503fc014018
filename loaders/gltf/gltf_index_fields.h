// The glTF members whose numbers are indices or byte counts. tinygltf takes one that is not a
// JSON integer (1e30, 0.5, -1, 4294967296) as absent, so such numbers are refused before it reads
// the document, naming their JSON path.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace radiant {

// One step of a JSON path: a member's name, or an element of the array named `name`.
struct JsonStep {
  std::string name;
  bool element = false;
};

enum class GltfNumberKind {
  any,    // a number of any value (a factor, a coordinate, extras)
  index,  // an index or an enum: an integer in [0, 2^31)
  size,   // a byte offset, length, stride or count: an integer in [0, 2^53)
};

// What the number at `path` (root first) must be.
GltfNumberKind gltf_number_kind(const std::vector<JsonStep>& path);

// "" when `text` (a JSON number as written) is a `kind` (any finite double for `any`), else why
// not, quoting at most 40 bytes.
std::string gltf_number_problem(GltfNumberKind kind, std::string_view text);

}  // namespace radiant
