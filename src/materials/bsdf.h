// The path tracer's BSDF at one surface point, seen from one outgoing direction. The lobe frame
// and selection probabilities are worked out once per path vertex and shared by light sampling
// (eval, pdf) and BSDF sampling. Directions are world-space unit vectors pointing away
// from the surface; `n` is the shading normal on the side the material was authored (the
// integrator flips it for double-sided hits).
#pragma once

#include <optional>
#include <variant>

#include "materials/bsdf_models.h"

namespace radiant {

// Each model's direction-independent part, and its lobes seen from one wo. Unlit surfaces
// (std::monostate) show their color and scatter nothing.
using BsdfParams =
    std::variant<std::monostate, LambertParams, PhongWeights, MetallicRoughnessParams, LayeredParams>;
using BsdfLobes = std::variant<std::monostate, LambertLobes, PhongLobes, MetallicRoughnessLobes, LayeredLobes>;

// The part of a material's BSDF that does not depend on directions: worked out once per
// material when the material is the same at every hit (no textures), once per hit otherwise.
class BsdfMaterial {
 public:
  explicit BsdfMaterial(const SurfaceMaterial& m);
  // The Lambert parameters when the material is exactly Lambertian, else null.
  const LambertParams* lambert() const { return std::get_if<LambertParams>(&params_); }
  // The metallic-roughness parameters when the material has that model without layers, else null.
  const MetallicRoughnessParams* metallic_roughness() const { return std::get_if<MetallicRoughnessParams>(&params_); }
  // The Phong weights when the material has the Phong model and is not exactly Lambertian, else null.
  const PhongWeights* phong() const { return std::get_if<PhongWeights>(&params_); }

 private:
  friend class Bsdf;
  BsdfParams params_;
};

class Bsdf {
 public:
  // `tangent` (world space, zero when unknown) orients anisotropic lobes (KHR_materials_anisotropy);
  // `coat_normal` (world space, on n's side; zero: n) is a clearcoat's own shading normal.
  Bsdf(const BsdfMaterial& material, vec3 n, vec3 wo, vec3 tangent = {}, vec3 coat_normal = {});
  Bsdf(const SurfaceMaterial& m, vec3 n, vec3 wo, vec3 tangent = {}, vec3 coat_normal = {})
      : Bsdf(BsdfMaterial(m), n, wo, tangent, coat_normal) {}

  // f(wo, wi) * |dot(n, wi)| for the non-delta lobes. The Lambertian branch, the commonest and
  // a few instructions, is forced inline: called, its wi came in registers, was stored on the
  // stack and read back a float at a time before the first multiplication.
  [[gnu::always_inline]] color3 eval(vec3 wi) const {
    if (auto* l = std::get_if<LambertLobes>(&lobes_)) return eval_world(*l, wi);
    return eval_framed(wi);
  }
  // Solid-angle pdf that sample() picks wi through a non-delta lobe.
  float pdf(vec3 wi) const;
  // eval(wi), with pdf(wi) in `pdf`: cheaper than the two apart.
  [[gnu::always_inline]] color3 eval(vec3 wi, float& pdf) const {
    if (auto* l = std::get_if<LambertLobes>(&lobes_)) return eval_world(*l, wi, pdf);
    return eval_framed(wi, pdf);
  }
  // Samples a direction; u_lobe picks a lobe, u the direction within it. nullopt when absorbed.
  std::optional<BsdfSample> sample(float u_lobe, vec2 u) const;
  // sample(u_lobe, u) with `cosine` = sample_cosine_hemisphere(u) worked out already (a batch's
  // at once, in SIMD): the diffuse and sheen lobes take it instead of warping u again.
  std::optional<BsdfSample> sample(float u_lobe, vec2 u, vec3 cosine) const;
  // False when at most one lobe can be chosen: sample() then ignores u_lobe, and the path
  // tracer skips drawing it. Inline for the models of one lobe, asked at every path vertex.
  bool chooses_lobe() const {
    return !std::holds_alternative<std::monostate>(lobes_) && !std::holds_alternative<LambertLobes>(lobes_) &&
           mixes_lobes();
  }

 private:
  bool mixes_lobes() const;  // chooses_lobe() for the models that may have several lobes
  // eval() for the models with a local frame, out of line: inlined, their code made every call
  // save registers, the Lambertian's too.
  color3 eval_framed(vec3 wi) const;
  color3 eval_framed(vec3 wi, float& pdf) const;

  // Both samples: the diffuse lobes warp u themselves when `cosine` is null.
  std::optional<BsdfSample> sample_with(float u_lobe, vec2 u, const vec3* cosine) const;

  BsdfLobes lobes_;
};

// True when the material has only delta lobes (mirror, smooth glass): light sampling is useless.
// Asked at every path vertex, so inline for the Phong model and for a glTF material with a
// diffuse base (the common answers; the rest works out roughness and layers).
bool is_layered_metallic_roughness_pure_delta(const SurfaceMaterial& m);
inline bool is_pure_delta(const SurfaceMaterial& m) {
  if (m.unlit) return true;
  if (m.model != MaterialModel::metallic_roughness) return is_phong_pure_delta(m);
  if (has_metallic_roughness_diffuse(m)) return false;
  return is_layered_metallic_roughness_pure_delta(m);
}
// Hemispherical albedo estimate used for the albedo AOV (base color or kd, clamped to [0,1]).
color3 bsdf_albedo(const SurfaceMaterial& m);

}  // namespace radiant
