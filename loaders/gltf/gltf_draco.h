// KHR_draco_mesh_compression: compressed primitives are decoded (Debian's libdraco) into plain
// buffers before the meshes are converted, so that every later check and conversion reads them
// like any other accessor.
#pragma once

#include "gltf/gltf_context.h"

namespace radiant {

// tinygltf 2.7 refuses an indices accessor without a bufferView, which is how a Draco primitive's
// accessors are written. Gives the file's bytes (a .gltf's JSON, or a whole GLB) with each such
// accessor pointed at its primitive's Draco bufferView until decode_draco_primitives points it at
// the decoded indices, into `rewritten`; false (and `rewritten` untouched) when no primitive
// needs it.
bool with_draco_index_views(const std::string& file_bytes, bool binary, std::string& rewritten);

// Decodes every primitive carrying KHR_draco_mesh_compression in `model` (the model `context`
// reads): its attribute and index accessors are pointed at a new buffer holding the decoded
// values (FLOAT attributes, UNSIGNED_INT indices) and the extension is removed. The decoded
// bytes, and the decoder's own copy, are charged before decoding; counts that differ from the
// accessors' are errors naming the primitive.
void decode_draco_primitives(tinygltf::Model& model, GltfContext& context);

}  // namespace radiant
