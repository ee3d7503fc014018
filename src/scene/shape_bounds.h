// The box around an analytic shape (sphere, plane, cylinder, tube), for scene bounds and the BVH.
#pragma once

#include "scene/scene_desc.h"

namespace radiant {

// World-space bounds; infinite shapes get finite bounds of +-`infinite_extent`.
void shape_bounds(const ShapeDesc& shape, float infinite_extent, vec3& lower, vec3& upper);

}  // namespace radiant
