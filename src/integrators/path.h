// The unidirectional path tracer: next-event estimation with multiple importance sampling.
#pragma once

#include "integrators/render_context.h"

namespace radiant {

// The path tracer compiled for the smallest effect set covering `effects`.
Integrator select_path(uint32_t effects);

}  // namespace radiant
