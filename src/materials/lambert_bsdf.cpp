// The Lambert BSDF, kd / pi, evaluated against the normal directly: the local frame is built
// only when a direction is sampled.
#include "materials/bsdf_models.h"
#include "materials/shading_frame.h"

namespace radiant {

LambertLobes make_lambert_lobes(const LambertParams& params, vec3 n, vec3 wo) {
  LambertLobes l;
  l.albedo = params.albedo;
  float cos_o = dot(n, wo);
  l.n = cos_o < 0 ? -n : n;  // as the Phong model: seen from behind, the surface faces wo
  l.valid = std::abs(cos_o) > lambert_min_cosine && std::isfinite(cos_o) && max_component(params.albedo) > 0;
  return l;
}

std::optional<BsdfSample> sample_world(const LambertLobes& l, vec2 u) {
  return sample_warped(l, sample_cosine_hemisphere(u));
}

std::optional<BsdfSample> sample_warped(const LambertLobes& l, vec3 local) {
  // One named result on every path, so that it is built where the caller wants it (NRVO). A
  // local copied into the return value is written as floats and read back as 16-byte blocks,
  // which stalls the CPU's store forwarding: that took a third of this function's time.
  std::optional<BsdfSample> s;
  if (!l.valid) return s;
  if (!(local.z >= lambert_min_cosine)) return s;
  s.emplace();
  s->wi = to_world(make_shading_frame(l.n), local);
  s->weight = l.albedo;  // f cos / pdf: the cosine and 1/pi cancel
  s->pdf = local.z * inv_pi;
  return s;
}

}  // namespace radiant
