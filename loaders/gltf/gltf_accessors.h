// Reading glTF accessors: every component type, normalized integers, byte strides and sparse
// storage, with bounds checked against the bufferView and buffer before any byte is read.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gltf/gltf_context.h"

namespace radiant {

// Accessor `index` as floats, `components` per element (1 for SCALAR ... 4 for VEC4); normalized
// integers map to [0,1] or [-1,1]. `types` lists the accepted element types (TINYGLTF_TYPE_*).
// `where` names the referring property in messages.
std::vector<float> read_accessor_floats(const GltfContext& context, int index, const std::string& where,
                                        const std::vector<int>& types, int& components);

// An index accessor: SCALAR of unsigned byte, short or int.
std::vector<uint32_t> read_accessor_indices(const GltfContext& context, int index, const std::string& where);

// The bytes of bufferView `view_index` (its byteLength in `length`), checked against its buffer.
const unsigned char* buffer_view_bytes(const GltfContext& context, int view_index, const std::string& where,
                                       size_t& length);

// Number of elements accessor `index` declares (after checking the index).
size_t accessor_count(const GltfContext& context, int index, const std::string& where);

}  // namespace radiant
