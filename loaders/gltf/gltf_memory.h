// What loading a glTF costs in memory, estimated before the memory is taken so that the budget
// can refuse first: tinygltf's model from the counts of the JSON document, and decoded images
// from their headers. The constants were measured (peak resident memory of tinygltf 2.7 loading
// documents of each kind); docs/gltf-obj.md lists them.
#pragma once

#include <cstdint>

#include "gltf/gltf_declarations.h"

namespace radiant {

// The JSON tree tinygltf parses (about 190 bytes a value, member names included), the structs
// it makes of every counted element (about twice their size once their strings and maps are
// filled), and two copies of the text's strings.
uint64_t gltf_model_bytes(const GltfJsonCounts& counts, uint64_t json_bytes);

// Decoding one PNG or JPEG of `width` x `height`: stb_image's component planes and output,
// tinygltf's copy and radiant's texels, each at most four channels of `bytes_per_channel`.
uint64_t gltf_image_decode_bytes(int width, int height, int bytes_per_channel);

}  // namespace radiant
