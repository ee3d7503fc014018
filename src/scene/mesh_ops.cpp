#include "scene/mesh_ops.h"

#include <cmath>
#include <type_traits>
#include <utility>

namespace radiant {

static vec3 face_normal_times_two_area(const MeshDesc& mesh, size_t t) {
  const vec3& a = mesh.positions[mesh.indices[t]];
  const vec3& b = mesh.positions[mesh.indices[t + 1]];
  const vec3& c = mesh.positions[mesh.indices[t + 2]];
  return cross(b - a, c - a);
}

size_t drop_degenerate_triangles(MeshDesc& mesh) {
  size_t kept = 0, before = mesh.indices.size() / 3;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    uint32_t i = mesh.indices[t], j = mesh.indices[t + 1], k = mesh.indices[t + 2];
    if (i == j || j == k || i == k) continue;
    if (!(length_squared(face_normal_times_two_area(mesh, t)) > 0)) continue;
    mesh.indices[kept * 3] = i, mesh.indices[kept * 3 + 1] = j, mesh.indices[kept * 3 + 2] = k;
    ++kept;
  }
  mesh.indices.resize(kept * 3);
  return before - kept;
}

// Sum of the face normals around each vertex, each weighted by twice its triangle's area.
static std::vector<vec3> area_weighted_normals(const MeshDesc& mesh) {
  std::vector<vec3> sums(mesh.positions.size(), vec3{0, 0, 0});
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    vec3 n = face_normal_times_two_area(mesh, t);
    for (int corner = 0; corner < 3; ++corner) sums[mesh.indices[t + corner]] += n;
  }
  return sums;
}

// An unused or fully cancelled vertex still needs a valid normal: +Z is as good as any.
static vec3 unit_or_default(vec3 n) {
  float l = length(n);
  return l > 0 && std::isfinite(l) ? n / l : vec3{0, 0, 1};
}

void generate_normals(MeshDesc& mesh) {
  mesh.normals = area_weighted_normals(mesh);
  for (vec3& n : mesh.normals) n = unit_or_default(n);
}

// Gives every triangle its own three vertices (every attribute copied).
static void unweld_triangles(MeshDesc& mesh) {
  auto unweld = [&](auto& values) {
    if (values.empty()) return;
    std::remove_reference_t<decltype(values)> corners;
    corners.reserve(mesh.indices.size());
    for (uint32_t index : mesh.indices) corners.push_back(values[index]);
    values = std::move(corners);
  };
  unweld(mesh.positions), unweld(mesh.normals), unweld(mesh.tangents);
  unweld(mesh.texcoords0), unweld(mesh.texcoords1), unweld(mesh.colors);
  for (size_t i = 0; i < mesh.indices.size(); ++i) mesh.indices[i] = uint32_t(i);
}

void shade_flat(MeshDesc& mesh, bool normal_mapped) {
  mesh.normals.clear();
  mesh.tangents.clear();
  if (!normal_mapped) return;
  unweld_triangles(mesh);
  generate_normals(mesh);
}

size_t repair_normals(MeshDesc& mesh) {
  if (mesh.normals.size() != mesh.positions.size()) {
    generate_normals(mesh);
    return mesh.positions.size();
  }
  std::vector<vec3> generated;
  size_t bad = 0;
  for (size_t v = 0; v < mesh.normals.size(); ++v) {
    float l = length(mesh.normals[v]);
    if (l > 0 && std::isfinite(l)) {
      mesh.normals[v] = mesh.normals[v] / l;
      continue;
    }
    if (generated.empty()) generated = area_weighted_normals(mesh);
    mesh.normals[v] = unit_or_default(generated[v]);
    ++bad;
  }
  return bad;
}

// Tangents along +u (Lengyel's method), orthogonalized against the normal (Gram-Schmidt); w is
// the handedness of the (tangent, bitangent, normal) frame.
void generate_tangents(MeshDesc& mesh) {
  if (mesh.texcoords0.size() != mesh.positions.size()) return;
  if (mesh.normals.size() != mesh.positions.size()) generate_normals(mesh);
  std::vector<vec3> tangents(mesh.positions.size(), vec3{0, 0, 0});
  std::vector<vec3> bitangents(mesh.positions.size(), vec3{0, 0, 0});
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    uint32_t i[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
    vec3 e1 = mesh.positions[i[1]] - mesh.positions[i[0]], e2 = mesh.positions[i[2]] - mesh.positions[i[0]];
    vec2 d1 = mesh.texcoords0[i[1]] - mesh.texcoords0[i[0]], d2 = mesh.texcoords0[i[2]] - mesh.texcoords0[i[0]];
    float det = d1.x * d2.y - d2.x * d1.y;
    if (!(std::abs(det) > 1e-20f)) continue;  // zero-area in UV: no defined direction
    vec3 tangent = (e1 * d2.y - e2 * d1.y) / det, bitangent = (e2 * d1.x - e1 * d2.x) / det;
    if (!is_finite(tangent) || !is_finite(bitangent)) continue;
    for (uint32_t v : i) tangents[v] += tangent, bitangents[v] += bitangent;
  }
  mesh.tangents.resize(mesh.positions.size());
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    vec3 n = mesh.normals[v];
    vec3 tangent = tangents[v] - n * dot(n, tangents[v]);
    if (!(length(tangent) > 1e-12f)) {
      vec3 b;
      orthonormal_basis(n, tangent, b);  // any tangent will do where UVs give none
    }
    tangent = normalize(tangent);
    float handedness = dot(cross(n, tangent), bitangents[v]) < 0 ? -1.0f : 1.0f;
    mesh.tangents[v] = {tangent.x, tangent.y, tangent.z, handedness};
  }
}

}  // namespace radiant
