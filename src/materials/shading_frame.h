// The local shading frame in which BSDF lobes are written: z is the shading normal.
#pragma once

#include "math/vec.h"

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

// A direction around +z with density cos(theta)/pi (Malley's method).
inline vec3 sample_cosine_hemisphere(vec2 u) {
  float r = std::sqrt(u.x), phi = 2 * pi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1 - u.x))};
}

// Mirror of a local direction about the +z normal.
inline vec3 reflect_local(vec3 w) { return {-w.x, -w.y, w.z}; }

}  // namespace radiant
