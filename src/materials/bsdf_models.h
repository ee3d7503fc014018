// The BSDF families behind materials/bsdf.h. Each has a part that depends on the material
// only (worked out once per material when it has no textures) and its lobes seen from one
// outgoing direction: that part plus the local frame and what depends on wo, then evaluated,
// queried for pdfs and sampled in that frame (Lambert needs no frame but to sample).
#pragma once

#include <optional>

#include "materials/shading_frame.h"
#include "materials/surface.h"

namespace radiant {

// Lambert: the matte surface (a Phong material with only kd). The commonest surface gets its
// own model because it needs no local frame to evaluate, only to sample, and no lobe choice.
struct LambertParams {
  color3 albedo;  // the energy-conserving kd
};
struct LambertLobes : LambertParams {
  bool valid = false;
  vec3 n;  // the normal on wo's side
};
LambertLobes make_lambert_lobes(const LambertParams& params, vec3 n, vec3 wo);
// These take world-space directions.
color3 eval_world(const LambertLobes& l, vec3 wi);
float pdf_world(const LambertLobes& l, vec3 wi);
std::optional<BsdfSample> sample_world(const LambertLobes& l, vec2 u);

// Phong: normalized diffuse + modified-Phong lobe, delta mirror (kr) and delta transmission (kt).
// The weights and lobe choice depend on the material only.
struct PhongWeights {
  bool scatters = false;  // some lobe has weight
  float ior = 1;
  float exponent = 1;
  color3 kd, ks, kr, kt;  // energy-conserving weights
  float p_diffuse = 0, p_glossy = 0, p_mirror = 0, p_transmission = 0;
};
PhongWeights make_phong_weights(const SurfaceMaterial& m);
struct PhongLobes : PhongWeights {
  bool valid = false;
  ShadingFrame frame;  // z = the normal on wo's side
  vec3 wo;             // local, wo.z > 0
  float eta = 1.5f;    // n_transmitted / n_incident seen from wo
};
PhongLobes make_phong_lobes(const PhongWeights& w, vec3 n, vec3 wo);
color3 eval_local(const PhongLobes& l, vec3 wi);
float pdf_local(const PhongLobes& l, vec3 wi);
std::optional<BsdfSample> sample_local(const PhongLobes& l, float u_lobe, vec2 u);
bool is_phong_pure_delta(const SurfaceMaterial& m);

// glTF metallic-roughness: GGX specular over Lambert, metal, and (rough or smooth) transmission.
// The parameters depend on the material only; the lobe choice also on wo (Fresnel).
struct MetallicRoughnessParams {
  float alpha = 1;
  bool smooth = false;  // specular lobes are delta
  float ior = 1.5f;     // of the coating, always entered from outside
  color3 base;
  float metal = 0, plastic = 0, glass = 0;  // mix weights, summing to 1
  float fade = 1;                            // strength of the plastic's specular coating
};
MetallicRoughnessParams make_metallic_roughness_params(const SurfaceMaterial& m);
struct MetallicRoughnessLobes : MetallicRoughnessParams {
  bool valid = false;
  ShadingFrame frame;  // z = the normal on wo's side
  vec3 wo;             // local, wo.z > 0
  float eta = 1.5f;    // of the glass: n_transmitted / n_incident seen from wo
  float p_specular = 0, p_diffuse = 0, p_transmission = 0;
};
MetallicRoughnessLobes make_metallic_roughness_lobes(const MetallicRoughnessParams& params, vec3 n, vec3 wo);
color3 eval_local(const MetallicRoughnessLobes& l, vec3 wi);
float pdf_local(const MetallicRoughnessLobes& l, vec3 wi);
std::optional<BsdfSample> sample_local(const MetallicRoughnessLobes& l, float u_lobe, vec2 u);
bool is_metallic_roughness_pure_delta(const SurfaceMaterial& m);

}  // namespace radiant
