// What a ray that leaves the scene sees.
#pragma once

#include "integrators/render_context.h"

namespace radiant {

template <uint32_t E>
color3 background_radiance(const RenderContext& ctx, vec3 direction) {
  if (!enabled<E>(ctx.effects, effect_environment)) return {0, 0, 0};
  return eval_environment(*ctx.lights, normalize(direction));
}

}  // namespace radiant
