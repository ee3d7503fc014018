#include "gltf/gltf_deform.h"

#include <cmath>

#include "gltf/gltf_accessors.h"

namespace radiant {

bool MeshPose::deforms() const {
  if (!joint_matrices.empty()) return true;
  for (double w : weights)
    if (w != 0) return true;
  return false;
}

namespace {

// Accessor `index` as `components`-wide floats, one per vertex, all finite.
std::vector<float> per_vertex(const GltfContext& context, int index, int type, size_t vertex_count,
                              const std::string& where) {
  int components = 0;
  std::vector<float> values = read_accessor_floats(context, index, where, {type}, components);
  for (size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i])) context.fail(where, "non-finite value in element " + std::to_string(i / size_t(components)));
  if (values.size() / size_t(components) != vertex_count)
    context.fail(where, std::to_string(values.size() / size_t(components)) + " elements, but POSITION has " +
                            std::to_string(vertex_count));
  return values;
}

// mesh[i] += weight * delta[i] for one target attribute, if the target has it.
template <typename Add>
void add_target(const GltfContext& context, const std::map<std::string, int>& target, const char* name,
                size_t vertex_count, const std::string& where, Add add) {
  auto found = target.find(name);
  if (found == target.end()) return;
  std::vector<float> delta = per_vertex(context, found->second, TINYGLTF_TYPE_VEC3, vertex_count, where + "." + name);
  for (size_t i = 0; i < vertex_count; ++i) add(i, vec3{delta[i * 3], delta[i * 3 + 1], delta[i * 3 + 2]});
}

// a + s * b, for blending affine matrices.
void add_scaled(mat4& a, const mat4& b, float s) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) a.m[r][c] += s * b.m[r][c];
}

}  // namespace

void apply_morph_targets(const GltfContext& context, const tinygltf::Primitive& primitive,
                         const std::vector<double>& weights, MeshDesc& mesh, const std::string& where) {
  size_t count = mesh.positions.size();
  for (size_t t = 0; t < primitive.targets.size() && t < weights.size(); ++t) {
    float weight = float(weights[t]);
    if (weight == 0) continue;
    std::string at = where + "." + element("targets", t);
    const auto& target = primitive.targets[t];
    context.charge(count * 12, at);
    add_target(context, target, "POSITION", count, at, [&](size_t i, vec3 d) { mesh.positions[i] += d * weight; });
    if (!mesh.normals.empty())
      add_target(context, target, "NORMAL", count, at, [&](size_t i, vec3 d) { mesh.normals[i] += d * weight; });
    if (!mesh.tangents.empty())
      add_target(context, target, "TANGENT", count, at, [&](size_t i, vec3 d) {
        vec4& t4 = mesh.tangents[i];
        t4 = {t4.x + d.x * weight, t4.y + d.y * weight, t4.z + d.z * weight, t4.w};
      });
  }
  for (vec3& n : mesh.normals) n = normalize(n);
}

void apply_skin(const GltfContext& context, const tinygltf::Primitive& primitive,
                const std::vector<mat4>& joint_matrices, MeshDesc& mesh, const std::string& where) {
  size_t count = mesh.positions.size();
  context.charge(count * sizeof(mat4), where + ": skinning");
  std::vector<mat4> blended(count);
  for (mat4& m : blended) m.m[0][0] = m.m[1][1] = m.m[2][2] = 0;  // zero affine part; summed below
  std::vector<float> total(count, 0.0f);
  for (int set = 0;; ++set) {
    std::string joints_name = "JOINTS_" + std::to_string(set), weights_name = "WEIGHTS_" + std::to_string(set);
    auto joints_it = primitive.attributes.find(joints_name), weights_it = primitive.attributes.find(weights_name);
    if (joints_it == primitive.attributes.end() && weights_it == primitive.attributes.end()) break;
    if (joints_it == primitive.attributes.end() || weights_it == primitive.attributes.end())
      context.fail(where + ".attributes", joints_name + " and " + weights_name + " must come together");
    std::string joints_at = where + ".attributes." + joints_name, weights_at = where + ".attributes." + weights_name;
    context.charge(count * 32, joints_at);
    std::vector<float> joints = per_vertex(context, joints_it->second, TINYGLTF_TYPE_VEC4, count, joints_at);
    std::vector<float> weights = per_vertex(context, weights_it->second, TINYGLTF_TYPE_VEC4, count, weights_at);
    for (size_t i = 0; i < count; ++i)
      for (int k = 0; k < 4; ++k) {
        float weight = weights[i * 4 + k], joint = joints[i * 4 + k];
        if (weight == 0) continue;
        if (weight < 0) context.fail(weights_at, "negative weight in element " + std::to_string(i));
        if (!(joint >= 0 && joint < float(joint_matrices.size())) || joint != std::floor(joint))
          context.fail(joints_at, "joint " + number_text(joint) + " of element " + std::to_string(i) +
                                      " out of range (" + std::to_string(joint_matrices.size()) + " joints)");
        add_scaled(blended[i], joint_matrices[size_t(joint)], weight);
        total[i] += weight;
      }
  }
  for (size_t i = 0; i < count; ++i) {
    // Unweighted vertices stay where they are; weights that do not sum to 1 are normalized.
    if (!(total[i] > 0)) continue;
    mat4 m = blended[i];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) m.m[r][c] /= total[i];
    mesh.positions[i] = transform_point(m, mesh.positions[i]);
    mat4 inverse;
    bool invertible = inverse_affine(m, inverse);
    if (!mesh.normals.empty()) mesh.normals[i] = invertible ? normalize(transform_normal(inverse, mesh.normals[i])) : mesh.normals[i];
    if (!mesh.tangents.empty()) {
      vec4& t = mesh.tangents[i];
      vec3 moved = normalize(transform_vector(m, {t.x, t.y, t.z}));
      t = {moved.x, moved.y, moved.z, t.w};
    }
  }
}

}  // namespace radiant
