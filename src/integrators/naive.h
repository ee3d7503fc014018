// Pure BSDF sampling without light sampling: the simple path tracer radiant's first users began
// with, kept for comparison and tests. Point, spot and directional lights cannot be hit by a
// sampled ray, so they contribute nothing in this mode.
#pragma once

#include "integrators/render_context.h"

namespace radiant {

Integrator select_naive(uint32_t effects);

}  // namespace radiant
