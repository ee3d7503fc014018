// Tangent-space normal mapping, and bump mapping from a height map.
#include "materials/surface.h"

namespace radiant {

vec3 apply_normal_map(vec3 n, vec4 tangent, vec3 tangent_space_normal) {
  // Gram-Schmidt: interpolated tangents are rarely orthogonal to the shading normal.
  vec3 t = {tangent.x, tangent.y, tangent.z};
  t = t - n * dot(n, t);
  vec3 b;
  if (length_squared(t) > 1e-12f && std::isfinite(length_squared(t))) {
    t = normalize(t);
    float handedness = tangent.w < 0 ? -1.0f : 1.0f;
    b = cross(n, t) * handedness;
  } else {
    orthonormal_basis(n, t, b);  // no usable tangent: any frame beats a NaN
  }
  vec3 local = tangent_space_normal;
  vec3 mapped = normalize(t * local.x + b * local.y + n * local.z);
  return is_finite(mapped) && length_squared(mapped) > 0.5f ? mapped : n;
}

vec3 apply_bump_map(vec3 n, vec3 dpdu, vec3 dpdv, vec2 height_slope) {
  vec3 bumped = cross(dpdu + n * height_slope.x, dpdv + n * height_slope.y);
  // The uv frame may be mirrored: the perturbed normal stays on the side of n.
  if (dot(cross(dpdu, dpdv), n) < 0) bumped = -bumped;
  bumped = normalize(bumped);
  return is_finite(bumped) && length_squared(bumped) > 0.5f ? bumped : n;
}

}  // namespace radiant
