// EXT_meshopt_compression: compressed bufferViews are decoded (Debian's libmeshoptimizer) into
// plain buffers before any accessor is read, so that every later check and conversion reads them
// like any other bufferView. Fallback buffers without data are never loaded.
#pragma once

#include <string>

#include "gltf/gltf_context.h"
#include "gltf/gltf_declarations.h"

namespace radiant {

inline const std::string meshopt_extension = "EXT_meshopt_compression";

// True for buffer `index` of a file using EXT_meshopt_compression that has no data of its own: a
// fallback (placeholder) buffer with no uri, other than a GLB's binary chunk (buffer 0). It is
// neither read nor charged; the bufferViews over it are decoded from their compressed data.
bool is_meshopt_placeholder(const GltfDeclarations& declared, size_t index, bool binary);

// tinygltf 2.7 refuses a .gltf buffer without uri and copies a GLB's binary chunk into every
// buffer without one. Gives the file's bytes (a .gltf's JSON, or a whole GLB) with each
// placeholder buffer turned into an empty one, into `rewritten`; false (and `rewritten`
// untouched) when there is none.
bool with_meshopt_placeholders(const std::string& file_bytes, bool binary, const GltfDeclarations& declared,
                               std::string& rewritten);

// Decodes every bufferView carrying EXT_meshopt_compression in `model` (the model `context`
// reads) into a buffer of its own (ATTRIBUTES, TRIANGLES and INDICES modes; NONE, OCTAHEDRAL,
// QUATERNION and EXPONENTIAL filters), points the view at it and removes the extension. The
// decoded size (count × byteStride) is charged before decoding; malformed data is an error
// naming the bufferView.
void decode_meshopt_views(tinygltf::Model& model, GltfContext& context);

}  // namespace radiant
