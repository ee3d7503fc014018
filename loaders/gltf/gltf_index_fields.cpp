#include "gltf/gltf_index_fields.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace radiant {

namespace {

// Members that hold an index into a top-level array, or an enum.
const std::string_view index_members[] = {
    "scene",   "camera",   "mesh",      "skin",      "skeleton",  "node",     "indices", "material",
    "bufferView", "buffer", "inverseBindMatrices", "sampler", "source", "input", "output", "index",
    "texCoord", "componentType", "mode",  "magFilter", "minFilter", "wrapS",    "wrapT",   "light",
    "variant", "target"};
// Members that hold a byte offset, length or stride, or an element count.
const std::string_view size_members[] = {"byteOffset", "byteLength", "byteStride", "count"};
// Arrays whose elements are indices.
const std::string_view index_arrays[] = {"children", "nodes", "joints", "variants"};

bool among(std::string_view name, const auto& names) {
  return std::find(std::begin(names), std::end(names), name) != std::end(names);
}

}  // namespace

GltfNumberKind gltf_number_kind(const std::vector<JsonStep>& path) {
  if (path.empty()) return GltfNumberKind::any;
  for (const JsonStep& step : path)
    if (step.name == "extras" && !step.element) return GltfNumberKind::any;  // the application's own data
  const JsonStep& last = path.back();
  if (last.element) return among(last.name, index_arrays) ? GltfNumberKind::index : GltfNumberKind::any;
  if (among(last.name, size_members)) return GltfNumberKind::size;
  if (among(last.name, index_members)) return GltfNumberKind::index;
  if (path.size() >= 2) {
    const JsonStep& parent = path[path.size() - 2];
    // attributes {"POSITION": 0} and morph targets [{"POSITION": 1}] name accessors.
    if ((parent.name == "attributes" && !parent.element) || (parent.name == "targets" && parent.element))
      return GltfNumberKind::index;
  }
  return GltfNumberKind::any;
}

std::string gltf_number_problem(GltfNumberKind kind, std::string_view text) {
  std::string shown(text.substr(0, 40));
  if (text.size() > 40) shown += "...";
  if (kind == GltfNumberKind::any) {
    // Only a number with an exponent or hundreds of digits can overflow: parse just those.
    bool may_overflow = text.size() > 300 || text.find_first_of("eE") != std::string_view::npos;
    if (may_overflow && !std::isfinite(std::strtod(std::string(text).c_str(), nullptr)))
      return shown + " is beyond the range of a double";
    return "";
  }
  const char* wanted = kind == GltfNumberKind::index ? "an integer from 0 to 2147483647"
                                                     : "an integer from 0 to 2^53";
  uint64_t limit = kind == GltfNumberKind::index ? 0x7fffffffull : 1ull << 53;
  bool digits = !text.empty() && text.size() <= 17 &&
                std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
  uint64_t value = 0;
  for (char c : text) value = digits ? value * 10 + uint64_t(c - '0') : 0;
  if (digits && value <= limit) return "";
  return shown + " is not " + wanted;
}

}  // namespace radiant
