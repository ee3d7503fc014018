// Cycles' sample clamps (--clamp-direct, --clamp-indirect): a light contribution whose channels
// add up to more than the limit is scaled down to it. What a path gathers at its first hit (and
// what the camera sees directly) is direct; what later vertices gather is indirect. Rare, very
// bright samples (fireflies) lose most of their light, so a clamped render is biased darker
// where light is concentrated (caustics, small bright emitters seen in reflections).
#pragma once

#include <cmath>

#include "integrators/render_context.h"

namespace radiant {

// `contribution` (the path's throughput included) gathered at vertex `vertex` of its path: 0 is
// the first hit, -1 the camera itself (what its ray sees). Light a bounce from vertex v finds
// (an emitter or the environment it hits) belongs to vertex v, as its light sample does.
inline color3 clamp_contribution(const RenderContext& ctx, color3 contribution, int vertex) {
  float limit = vertex <= 0 ? ctx.clamp_direct : ctx.clamp_indirect;
  if (!(limit > 0)) return contribution;
  float sum = std::fabs(contribution.x) + std::fabs(contribution.y) + std::fabs(contribution.z);
  return sum > limit ? contribution * (limit / sum) : contribution;
}

}  // namespace radiant
