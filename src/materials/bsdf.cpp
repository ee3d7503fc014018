// The path tracer's BSDF: dispatch on the material model, once per path vertex.
#include "materials/bsdf.h"

#include <initializer_list>
#include <type_traits>

#include "materials/lobe_sampling.h"
#include "materials/metallic_roughness.h"

namespace radiant {

namespace {

color3 clamp01(color3 c) { return min(max(c, {0, 0, 0}), {1, 1, 1}); }

BsdfParams make_params(const SurfaceMaterial& m) {
  if (m.unlit) return std::monostate{};
  if (m.model == MaterialModel::metallic_roughness) {
    // Metallic 0, no transmission, specularFactor 0: the glTF material that is exactly Lambertian.
    bool layered = m.clearcoat > 0 || max_component(m.sheen_color) > 0;
    bool matte = !(m.metallic > 0) && !(m.transmission > 0) && !(m.specular > 0) && !(m.diffuse_transmission > 0) &&
                 !layered;
    if (matte) return LambertParams{clamp01(m.base_color)};
    if (layered) return make_layered_params(m);
    return make_metallic_roughness_params(m);
  }
  PhongWeights phong = make_phong_weights(m);
  bool matte = phong.scatters && phong.p_glossy == 0 && phong.p_mirror == 0 && phong.p_transmission == 0;
  if (matte) return LambertParams{phong.kd};
  return phong;
}

}  // namespace

BsdfMaterial::BsdfMaterial(const SurfaceMaterial& m) : params_(make_params(m)) {}

namespace {

// Converts to `make()`'s result, so that the variant constructs its alternative straight from
// the call (copy elision). Building the lobes in a temporary and copying them in would read
// back as 16-byte blocks what was just written as floats, which stalls the CPU's store
// forwarding on every path vertex.
template <class Make>
struct BuiltBy {
  Make make;
  operator std::invoke_result_t<Make>() const { return make(); }
};
template <class Make>
BuiltBy(Make) -> BuiltBy<Make>;  // clang before 17 deduces no aggregate's arguments by itself

// The lobes, returned as the variant itself and built in its storage: emplacing into an
// existing variant goes through a temporary variant in libstdc++.
BsdfLobes make_lobes(const BsdfParams& params, vec3 n, vec3 wo, vec3 tangent, vec3 coat_normal) {
  if (auto* p = std::get_if<LambertParams>(&params))
    return BsdfLobes(std::in_place_type<LambertLobes>, BuiltBy{[&] { return make_lambert_lobes(*p, n, wo); }});
  if (auto* w = std::get_if<PhongWeights>(&params))
    return BsdfLobes(std::in_place_type<PhongLobes>, BuiltBy{[&] { return make_phong_lobes(*w, n, wo); }});
  if (auto* m = std::get_if<MetallicRoughnessParams>(&params))
    return BsdfLobes(std::in_place_type<MetallicRoughnessLobes>,
                     BuiltBy{[&] { return make_metallic_roughness_lobes(*m, n, wo, tangent); }});
  if (auto* c = std::get_if<LayeredParams>(&params))
    return BsdfLobes(std::in_place_type<LayeredLobes>, BuiltBy{[&] { return make_layered_lobes(*c, n, wo, tangent, coat_normal); }});
  return {};
}

}  // namespace

Bsdf::Bsdf(const BsdfMaterial& material, vec3 n, vec3 wo, vec3 tangent, vec3 coat_normal)
    : lobes_(make_lobes(material.params_, n, wo, tangent, coat_normal)) {}

color3 Bsdf::eval_framed(vec3 wi) const {
  if (auto* l = std::get_if<PhongLobes>(&lobes_)) return eval_local(*l, to_local(l->frame, wi));
  if (auto* l = std::get_if<MetallicRoughnessLobes>(&lobes_)) return eval_local(*l, to_local(l->frame, wi));
  if (auto* l = std::get_if<LayeredLobes>(&lobes_)) return eval_local(*l, to_local(l->frame, wi));
  return {0, 0, 0};
}

float Bsdf::pdf(vec3 wi) const {
  if (auto* l = std::get_if<LambertLobes>(&lobes_)) return pdf_world(*l, wi);
  if (auto* l = std::get_if<PhongLobes>(&lobes_)) return pdf_local(*l, to_local(l->frame, wi));
  if (auto* l = std::get_if<MetallicRoughnessLobes>(&lobes_)) return pdf_local(*l, to_local(l->frame, wi));
  if (auto* l = std::get_if<LayeredLobes>(&lobes_)) return pdf_local(*l, to_local(l->frame, wi));
  return 0;
}

color3 Bsdf::eval_framed(vec3 wi, float& pdf) const {
  if (auto* l = std::get_if<PhongLobes>(&lobes_)) return eval_with_pdf(*l, to_local(l->frame, wi), pdf);
  if (auto* l = std::get_if<MetallicRoughnessLobes>(&lobes_)) return eval_with_pdf(*l, to_local(l->frame, wi), pdf);
  if (auto* l = std::get_if<LayeredLobes>(&lobes_)) return eval_with_pdf(*l, to_local(l->frame, wi), pdf);
  pdf = 0;
  return {0, 0, 0};
}

std::optional<BsdfSample> Bsdf::sample_with(float u_lobe, vec2 u, const vec3* cosine) const {
  if (auto* l = std::get_if<LambertLobes>(&lobes_)) return cosine ? sample_warped(*l, *cosine) : sample_world(*l, u);
  if (auto* l = std::get_if<PhongLobes>(&lobes_)) return sample_local(*l, u_lobe, u, cosine);
  if (auto* l = std::get_if<MetallicRoughnessLobes>(&lobes_)) return sample_local(*l, u_lobe, u, cosine);
  if (auto* l = std::get_if<LayeredLobes>(&lobes_)) return sample_local(*l, u_lobe, u, cosine);
  return std::nullopt;
}

std::optional<BsdfSample> Bsdf::sample(float u_lobe, vec2 u) const { return sample_with(u_lobe, u, nullptr); }

std::optional<BsdfSample> Bsdf::sample(float u_lobe, vec2 u, vec3 cosine) const {
  return sample_with(u_lobe, u, &cosine);
}

bool Bsdf::mixes_lobes() const {
  auto count = [](std::initializer_list<float> probabilities) {
    int n = 0;
    for (float p : probabilities) n += p > 0;
    return n;
  };
  if (auto* l = std::get_if<PhongLobes>(&lobes_))
    return count({l->p_diffuse, l->p_glossy, l->p_mirror, l->p_transmission}) > 1;
  if (auto* l = std::get_if<MetallicRoughnessLobes>(&lobes_))
    return count({l->p_specular, l->p_diffuse, l->p_diffuse_transmission, l->p_transmission}) > 1;
  if (auto* l = std::get_if<LayeredLobes>(&lobes_))
    return count({l->p_coat, l->p_sheen, 1 - l->p_coat - l->p_sheen}) > 1 ||
           count({l->base_lobes.p_specular, l->base_lobes.p_diffuse, l->base_lobes.p_diffuse_transmission,
                  l->base_lobes.p_transmission}) > 1;
  return false;
}

bool is_layered_metallic_roughness_pure_delta(const SurfaceMaterial& m) {
  bool rough_coat = m.clearcoat > 0 && roughness_to_alpha(m.clearcoat_roughness) >= smooth_alpha_threshold;
  return is_metallic_roughness_pure_delta(m) && !rough_coat && !(max_component(m.sheen_color) > 0);
}

color3 bsdf_albedo(const SurfaceMaterial& m) {
  return clamp01(m.model == MaterialModel::metallic_roughness ? m.base_color : m.kd);
}

}  // namespace radiant
