// The local shading frame in which BSDF lobes are written: z is the shading normal.
#pragma once

#include "math/vec.h"
#include "sampling/warp.h"  // sample_cosine_hemisphere: one definition for the whole renderer

namespace radiant {

struct ShadingFrame {
  vec3 t, b, n;
};

inline ShadingFrame make_shading_frame(vec3 n) {
  ShadingFrame frame;
  frame.n = n;
  orthonormal_basis(n, frame.t, frame.b);
  return frame;
}
inline vec3 to_local(const ShadingFrame& frame, vec3 w) {
  return {dot(w, frame.t), dot(w, frame.b), dot(w, frame.n)};
}
inline vec3 to_world(const ShadingFrame& frame, vec3 w) {
  return frame.t * w.x + frame.b * w.y + frame.n * w.z;
}

// Mirror of a local direction about the +z normal.
inline vec3 reflect_local(vec3 w) { return {-w.x, -w.y, w.z}; }

}  // namespace radiant
