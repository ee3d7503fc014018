// glTF points and lines (POINTS, LINES, LINE_LOOP, LINE_STRIP) to SceneDesc strokes: read in the
// mesh's object space with the primitive's material and COLOR_0, placed in world space by each
// node that shows the mesh.
#pragma once

#include "gltf/gltf_context.h"

namespace radiant {

// Appends to `strokes` the primitive of `mode` whose posed vertices (positions, colors) are in
// `vertices`, in the primitive's vertex `order`; a primitive with nothing to draw is skipped with
// a warning.
void add_primitive_stroke(GltfContext& context, int mode, const MeshDesc& vertices, const std::vector<uint32_t>& order,
                          int material, const std::string& where, std::vector<StrokeDesc>& strokes);

// Places `strokes` (object space) in the scene by `world`, charging them first.
void place_strokes(GltfContext& context, const std::vector<StrokeDesc>& strokes, const mat4& world);

}  // namespace radiant
