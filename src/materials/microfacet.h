// The isotropic GGX (Trowbridge-Reitz) microfacet distribution in the local shading frame (z up),
// with Smith height-correlated masking-shadowing and visible-normal sampling (Heitz 2018).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "math/lane.h"
#include "math/vec.h"

namespace radiant {

// Normal distribution D(m) for a microfacet normal m with m.z > 0. Inline, as is Lambda: the
// metallic-roughness model evaluates both twice per path vertex. Both are written over a lane
// (math/lane.h), a select for the early return, so that the batch's SIMD lanes call them too.
[[gnu::always_inline]] inline float ggx_distribution(vec3 m, float alpha) {
  float a2 = alpha * alpha;
  float d = m.z * m.z * (a2 - 1) + 1;
  float density = a2 / (pi * d * d);
  return m.z <= 0 ? 0.0f : density;
}
// Smith Lambda(w): the masking function is G1 = 1 / (1 + Lambda).
[[gnu::always_inline]] inline float ggx_lambda(vec3 w, float alpha) {
  float cos2 = w.z * w.z;
  float tan2 = std::max(0.0f, 1 - cos2) / cos2;
  float lambda = (std::sqrt(1 + alpha * alpha * tan2) - 1) / 2;
  return cos2 <= 0 ? std::numeric_limits<float>::infinity() : lambda;
}
// Height-correlated masking-shadowing G2 from the Lambdas along wo and wi.
[[gnu::always_inline]] inline float ggx_masking_shadowing_of(float lambda_o, float lambda_i) {
  return 1 / (1 + lambda_o + lambda_i);
}
// Density of the visible normal m given Lambda along wo and D(m): G1(wo) * max(0, wo.m) * D(m) / wo.z.
[[gnu::always_inline]] inline float ggx_visible_density(vec3 wo, vec3 m, float lambda_o, float density) {
  return 1 / (1 + lambda_o) * std::max(0.0f, dot(wo, m)) * density / wo.z;
}
float ggx_masking(vec3 w, float alpha);
// Height-correlated masking-shadowing G2(wo, wi).
float ggx_masking_shadowing(vec3 wo, vec3 wi, float alpha);
// Samples a microfacet normal visible from wo (wo.z > 0) with density ggx_visible_normal_pdf.
vec3 sample_ggx_visible_normal(vec3 wo, float alpha, vec2 u);
// Density of visible normals: G1(wo) * max(0, wo.m) * D(m) / wo.z.
float ggx_visible_normal_pdf(vec3 wo, vec3 m, float alpha);

// The same for anisotropic GGX (KHR_materials_anisotropy): alpha.x along the frame's x axis,
// alpha.y along y. Separate functions, so that isotropic materials keep the cheaper ones. The
// metallic-roughness model forms G2 and the visible-normal density from these itself, keeping
// Lambda along wo once per vertex.
float ggx_distribution(vec3 m, vec2 alpha);
float ggx_lambda(vec3 w, vec2 alpha);
vec3 sample_ggx_visible_normal(vec3 wo, vec2 alpha, vec2 u);

}  // namespace radiant
