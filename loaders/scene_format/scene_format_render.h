// `@render`: render settings the file suggests (the command line overrides each one).
#pragma once

#include "scene_format/scene_format_context.h"

namespace radiant::scene_format {

// Largest image side, samples per pixel and depth accepted, so a file cannot ask for absurd work.
constexpr int max_image_side = 65536;
constexpr int max_samples_per_pixel = 1 << 20;
constexpr int max_render_depth = 1024;

// mode, spp, sampler, max-depth, width, height into SceneDesc::settings; background (0-255)
// into SceneDesc::environment.color.
void build_render_block(BuildContext& context, const Block& block);

}  // namespace radiant::scene_format
