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

// A model's lobe frame seen from wo: z is the normal turned to wo's side (only transmissive
// materials are seen from behind), wo is expressed in it, and eta = n_transmitted / n_incident
// for a surface of index `ior` authored with its outside along n.
struct FacingFrame {
  ShadingFrame frame;
  vec3 wo;
  float eta;
};
// A non-zero `tangent` (not parallel to n) sets the frame's x axis: the direction of an
// anisotropic lobe.
inline FacingFrame facing_frame(vec3 n, vec3 wo, float ior, vec3 tangent = {}) {
  bool from_inside = dot(n, wo) < 0;
  FacingFrame f;
  f.frame = make_shading_frame(from_inside ? -n : n);
  vec3 t = tangent - f.frame.n * dot(f.frame.n, tangent);
  if (length_squared(t) > 1e-12f) {
    f.frame.t = normalize(t);
    f.frame.b = cross(f.frame.n, f.frame.t);
  }
  f.wo = to_local(f.frame, wo);
  f.eta = from_inside ? 1 / ior : ior;
  return f;
}

// Mirror of a local direction about the +z normal.
inline vec3 reflect_local(vec3 w) { return {-w.x, -w.y, w.z}; }

}  // namespace radiant
