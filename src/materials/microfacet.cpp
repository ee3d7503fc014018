// GGX microfacet distribution, masking-shadowing and visible-normal sampling.
#include "materials/microfacet.h"

#include <limits>

namespace radiant {

float ggx_masking(vec3 w, float alpha) { return 1 / (1 + ggx_lambda(w, alpha)); }

float ggx_masking_shadowing(vec3 wo, vec3 wi, float alpha) {
  return ggx_masking_shadowing_of(ggx_lambda(wo, alpha), ggx_lambda(wi, alpha));
}

vec3 sample_ggx_visible_normal(vec3 wo, float alpha, vec2 u) { return sample_ggx_visible_normal(wo, {alpha, alpha}, u); }

vec3 sample_ggx_visible_normal(vec3 wo, vec2 alpha, vec2 u) {
  // Stretch the view so the distribution becomes the hemisphere configuration.
  vec3 vh = normalize(vec3{alpha.x * wo.x, alpha.y * wo.y, wo.z});
  float length2 = vh.x * vh.x + vh.y * vh.y;
  vec3 t1 = length2 > 0 ? vec3{-vh.y, vh.x, 0} / std::sqrt(length2) : vec3{1, 0, 0};
  vec3 t2 = cross(vh, t1);
  // A point on the projected disk, warped to the visible half of the hemisphere.
  float r = std::sqrt(u.x), phi = 2 * pi * u.y;
  float p1 = r * std::cos(phi), p2 = r * std::sin(phi);
  float s = 0.5f * (1 + vh.z);
  p2 = (1 - s) * std::sqrt(std::max(0.0f, 1 - p1 * p1)) + s * p2;
  vec3 nh = t1 * p1 + t2 * p2 + vh * std::sqrt(std::max(0.0f, 1 - p1 * p1 - p2 * p2));
  // Unstretch back to the ellipsoid configuration.
  return normalize(vec3{alpha.x * nh.x, alpha.y * nh.y, std::max(1e-6f, nh.z)});
}

float ggx_visible_normal_pdf(vec3 wo, vec3 m, float alpha) {
  if (wo.z <= 0) return 0;
  return ggx_visible_density(wo, m, ggx_lambda(wo, alpha), ggx_distribution(m, alpha));
}

float ggx_distribution(vec3 m, vec2 alpha) {
  if (m.z <= 0) return 0;
  float x = m.x / alpha.x, y = m.y / alpha.y;
  float d = x * x + y * y + m.z * m.z;
  return 1 / (pi * alpha.x * alpha.y * d * d);
}

float ggx_lambda(vec3 w, vec2 alpha) {
  float cos2 = w.z * w.z;
  if (cos2 <= 0) return std::numeric_limits<float>::infinity();
  float stretched = (alpha.x * w.x) * (alpha.x * w.x) + (alpha.y * w.y) * (alpha.y * w.y);
  return (std::sqrt(1 + stretched / cos2) - 1) / 2;
}

}  // namespace radiant
