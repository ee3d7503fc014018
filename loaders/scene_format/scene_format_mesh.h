// `@mesh`: an OBJ file included with a transform and an optional material override.
#pragma once

#include "scene_format/scene_format_context.h"

namespace radiant::scene_format {

// `file` (relative to the scene's folder), then either `translate`/`rotate`/`scale` (applied
// as translate * rotate * scale) or a row-major `matrix` of 12 or 16 numbers.
void build_mesh_block(BuildContext& context, const Block& block);

// The object-to-world transform of a @mesh block (exposed for tests).
mat4 mesh_transform(const BuildContext& context, const Block& block);

}  // namespace radiant::scene_format
