// Lights of the .scene format: `@light ambient|directional|point|spot`.
#pragma once

#include "scene_format/scene_format_context.h"

namespace radiant::scene_format {

// Converts the 0-255 color to internal intensity (scene_format_units.h); point and spot lights
// keep the classic attenuation 1 / (kc + kl d + kq d^2), default kc = 1, kl = kq = 0.
void build_light_block(BuildContext& context, const Block& block);

}  // namespace radiant::scene_format
