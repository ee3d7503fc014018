// A position footprint on a triangle turned into each uv set's footprint.
#include <algorithm>
#include <cmath>

#include "accel/scene_accel.h"

namespace radiant {

namespace {

// pbrt clamps derivatives to this, so a footprint along a grazing plane stays finite.
constexpr float largest_uv_derivative = 1e8f;

float clamp_derivative(float d) {
  return std::isfinite(d) ? std::clamp(d, -largest_uv_derivative, largest_uv_derivative) : 0.0f;
}

}  // namespace

void set_uv_footprint(const SceneAccel& accel, const HitId& id, vec3 dpdx, vec3 dpdy, SurfaceHit& hit) {
  if (id.instance < 0) return;
  const InstanceDesc& instance = accel.scene->instances[size_t(id.instance)];
  const MeshDesc& mesh = accel.scene->meshes[size_t(instance.mesh)];
  const uint32_t* tri = &mesh.indices[size_t(id.primitive) * 3];
  vec3 e1 = mesh.positions[tri[1]] - mesh.positions[tri[0]], e2 = mesh.positions[tri[2]] - mesh.positions[tri[0]];
  if (!accel.instance_identity[size_t(id.instance)])
    e1 = transform_vector(instance.transform, e1), e2 = transform_vector(instance.transform, e2);
  // The barycentric change (b1, b2) whose point e1 * b1 + e2 * b2 is nearest to dpdx (and dpdy).
  float a00 = dot(e1, e1), a01 = dot(e1, e2), a11 = dot(e2, e2);
  float inverse = 1 / (a00 * a11 - a01 * a01);
  if (!std::isfinite(inverse)) return;
  auto barycentric_change = [&](vec3 dp) {
    float b0 = dot(e1, dp), b1 = dot(e2, dp);
    return vec2{(a11 * b0 - a01 * b1) * inverse, (a00 * b1 - a01 * b0) * inverse};
  };
  vec2 bx = barycentric_change(dpdx), by = barycentric_change(dpdy);
  for (int set = 0; set < 2; ++set) {
    const std::vector<vec2>& uvs = set == 0 ? mesh.texcoords0 : mesh.texcoords1;
    if (uvs.empty()) continue;
    vec2 d1 = uvs[tri[1]] - uvs[tri[0]], d2 = uvs[tri[2]] - uvs[tri[0]];
    vec2 dx = d1 * bx.x + d2 * bx.y, dy = d1 * by.x + d2 * by.y;
    hit.attributes.duv_dx[set] = {clamp_derivative(dx.x), clamp_derivative(dx.y)};
    hit.attributes.duv_dy[set] = {clamp_derivative(dy.x), clamp_derivative(dy.y)};
  }
}

}  // namespace radiant
