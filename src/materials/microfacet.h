// The isotropic GGX (Trowbridge-Reitz) microfacet distribution in the local shading frame (z up),
// with Smith height-correlated masking-shadowing and visible-normal sampling (Heitz 2018).
#pragma once

#include "math/vec.h"

namespace radiant {

// Normal distribution D(m) for a microfacet normal m with m.z > 0.
float ggx_distribution(vec3 m, float alpha);
// Smith Lambda(w): the masking function is G1 = 1 / (1 + Lambda).
float ggx_lambda(vec3 w, float alpha);
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
