// What a ray that leaves the scene sees.
#pragma once

#include "integrators/render_context.h"
#include "lights/environment_light.h"

namespace radiant {

template <uint32_t E>
color3 background_radiance(const RenderContext& ctx, vec3 direction) {
  if (!enabled<E>(ctx.effects, effect_environment)) return {0, 0, 0};
  return eval_environment(*ctx.lights, normalize(direction));
}

// What a camera ray (also one past alpha cutouts) sees where it leaves the scene (--background).
template <uint32_t E>
color3 camera_background(const RenderContext& ctx, vec3 direction) {
  switch (ctx.camera_background) {
    case CameraBackground::environment: return background_radiance<E>(ctx, direction);
    case CameraBackground::backdrop:
      if (!enabled<E>(ctx.effects, effect_environment)) return {0, 0, 0};
      return eval_environment_backdrop(*ctx.lights, normalize(direction));
    case CameraBackground::color: return ctx.background_color;
    case CameraBackground::none: break;
  }
  return {0, 0, 0};
}

}  // namespace radiant
