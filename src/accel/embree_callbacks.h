// The functions Embree calls back during traversal: the analytic shapes' user geometry, and the
// filters that pass rays through triangle hits (alpha cut-outs, single-sided back faces).
#pragma once

#include <embree3/rtcore.h>

namespace radiant {

// The analytic shapes as one user geometry; its user data is the SceneAccel.
void shape_bounds_callback(const RTCBoundsFunctionArguments* args);
void shape_intersect_callback(const RTCIntersectFunctionNArguments* args);
void shape_occluded_callback(const RTCOccludedFunctionNArguments* args);

// Rejects hits on texels whose alpha is under the material's cutoff, so they are never hit.
// The geometry's user data is its mesh's SceneAccel::MeshFilter.
void alpha_mask_filter(const RTCFilterFunctionNArguments* args);

// The context filter of FaceCulling::single_sided_back: rejects hits on the back faces of
// single-sided meshes (SceneAccel::MeshFilter as the geometry's user data).
void cull_single_sided_back_faces(const RTCFilterFunctionNArguments* args);

}  // namespace radiant
