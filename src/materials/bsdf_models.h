// The two BSDF families behind the dispatch in bsdf.cpp; same contract as surface.h.
#pragma once

#include "materials/surface.h"

namespace radiant {

// glTF metallic-roughness: GGX specular over Lambert, metal, and (rough or smooth) transmission.
color3 eval_metallic_roughness(const SurfaceMaterial& m, vec3 n, vec3 wo, vec3 wi);
float sample_metallic_roughness_pdf(const SurfaceMaterial& m, vec3 n, vec3 wo, vec3 wi);
std::optional<BsdfSample> sample_metallic_roughness(const SurfaceMaterial& m, vec3 n, vec3 wo, float u_lobe,
                                                    vec2 u);
bool is_metallic_roughness_pure_delta(const SurfaceMaterial& m);

// Phong: normalized diffuse + modified-Phong lobe, delta mirror (kr) and delta transmission (kt).
color3 eval_phong(const SurfaceMaterial& m, vec3 n, vec3 wo, vec3 wi);
float sample_phong_pdf(const SurfaceMaterial& m, vec3 n, vec3 wo, vec3 wi);
std::optional<BsdfSample> sample_phong(const SurfaceMaterial& m, vec3 n, vec3 wo, float u_lobe, vec2 u);
bool is_phong_pure_delta(const SurfaceMaterial& m);

}  // namespace radiant
