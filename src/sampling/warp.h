// Warps from the unit square to directions and shapes, with their pdfs.
#pragma once

#include "math/vec.h"

namespace radiant {

// Cosine-weighted direction around +z; pdf = cos(theta) / pi.
vec3 sample_cosine_hemisphere(vec2 u);
// Uniform direction on the unit sphere; pdf = 1 / (4 pi).
vec3 sample_uniform_sphere(vec2 u);
// Uniform direction inside the cone around +z with cos(half-angle) = cos_max; pdf = 1/(2pi(1-cos_max)).
vec3 sample_uniform_cone(vec2 u, float cos_max);
// Uniform barycentrics (b1, b2) on a triangle: Heitz 2019's low-distortion mapping, written over
// a lane (math/lane.h, selects for its two halves) for the batch's SIMD lanes too.
[[gnu::always_inline]] inline vec2 sample_uniform_triangle(vec2 u) {
  bool lower = u.x < u.y;
  float half_x = u.x / 2, half_y = u.y / 2;
  return {lower ? half_x : u.x - half_y, lower ? u.y - half_x : half_y};
}
// Uniform point on the unit disk; pdf = 1 / pi.
vec2 sample_uniform_disk(vec2 u);
// Uniform point in the regular polygon with `corners` (>= 3) on the unit circle, one at +y.
vec2 sample_regular_polygon(vec2 u, int corners);
// Expresses local direction `d` (z = normal) in the frame of unit normal `n`.
vec3 to_world(vec3 n, vec3 d);

// Power heuristic (beta = 2) for multiple importance sampling.
[[gnu::always_inline]] inline float power_heuristic(float pdf_a, float pdf_b) {
  float a = pdf_a * pdf_a, b = pdf_b * pdf_b;
  return a + b > 0 ? a / (a + b) : 0.0f;
}

}  // namespace radiant
