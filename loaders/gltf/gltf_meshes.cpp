#include "gltf/gltf_meshes.h"

#include <cmath>

#include "gltf/gltf_accessors.h"
#include "gltf/gltf_deform.h"
#include "gltf/gltf_materials.h"
#include "gltf/gltf_strokes.h"
#include "gltf/gltf_variants.h"
#include "scene/mesh_ops.h"
#include "scene/scene_memory.h"

namespace radiant {

namespace {

// Every vertex attribute must be finite: a NaN color or texture coordinate reaches the AOVs and
// the texture lookups, where no sample check sees where it came from.
void check_finite(const GltfContext& context, const std::vector<float>& values, int components,
                  const std::string& where) {
  for (size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      context.fail(where, "non-finite value in element " + std::to_string(i / size_t(components)));
}

template <typename Vec, int N>
std::vector<Vec> attribute(const GltfContext& context, const tinygltf::Primitive& primitive, const char* name,
                           const std::vector<int>& types, size_t vertex_count, const std::string& where) {
  std::vector<Vec> out;
  auto it = primitive.attributes.find(name);
  if (it == primitive.attributes.end()) return out;
  std::string at = where + ".attributes." + name;
  int components = 0;
  std::vector<float> values = read_accessor_floats(context, it->second, at, types, components);
  check_finite(context, values, components, at);
  size_t count = values.size() / components;
  if (count != vertex_count)
    context.fail(at, std::to_string(count) + " elements, but POSITION has " + std::to_string(vertex_count));
  context.charge(count * sizeof(Vec), at);
  out.resize(count);
  for (size_t i = 0; i < count; ++i) {
    float v[4] = {0, 0, 0, 1};  // a missing alpha (COLOR_0 as VEC3) is opaque
    for (int c = 0; c < components && c < 4; ++c) v[c] = values[i * components + c];
    if constexpr (N == 2) out[i] = Vec{v[0], v[1]};
    else if constexpr (N == 3) out[i] = Vec{v[0], v[1], v[2]};
    else out[i] = Vec{v[0], v[1], v[2], v[3]};
  }
  return out;
}

// Triangle list from the vertex order of TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN (glTF 3.7.2.1).
std::vector<uint32_t> triangles_of(int mode, const std::vector<uint32_t>& order) {
  std::vector<uint32_t> out;
  size_t n = order.size();
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    out.assign(order.begin(), order.begin() + (n / 3) * 3);
  } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (size_t i = 0; i + 2 < n; ++i) {
      bool odd = i % 2 == 1;  // odd triangles swap their last two vertices to keep the winding
      out.insert(out.end(), {order[i], order[odd ? i + 2 : i + 1], order[odd ? i + 1 : i + 2]});
    }
  } else {
    for (size_t i = 1; i + 1 < n; ++i) out.insert(out.end(), {order[i], order[i + 1], order[0]});
  }
  return out;
}

std::vector<uint32_t> vertex_order(const GltfContext& context, const tinygltf::Primitive& primitive,
                                   size_t vertex_count, const std::string& where) {
  if (primitive.indices < 0) {
    context.charge(vertex_count * sizeof(uint32_t), where);
    std::vector<uint32_t> order(vertex_count);
    for (size_t i = 0; i < vertex_count; ++i) order[i] = uint32_t(i);
    return order;
  }
  std::vector<uint32_t> order = read_accessor_indices(context, primitive.indices, where + ".indices");
  for (uint32_t index : order)
    if (index >= vertex_count)
      context.fail(where + ".indices", "index " + std::to_string(index) + " out of range (" +
                                           std::to_string(vertex_count) + " vertices)");
  return order;
}

void fill_shading_frames(GltfContext& context, MeshDesc& mesh, bool has_normals, const std::string& where) {
  const MaterialDesc& material = context.scene.materials[mesh.material];
  // Normal maps (the coat's too) and anisotropy (KHR_materials_anisotropy) are written in the tangent frame.
  bool normal_maps = material.normal_texture.valid() || material.clearcoat_normal_texture.valid();
  bool needs_tangents = normal_maps || material.anisotropy_strength > 0;
  bool normal_mapped = needs_tangents && !mesh.texcoords0.empty();
  context.charge(shading_frame_bytes(mesh, needs_tangents), where);
  if (!has_normals) {
    // glTF 3.7.2.1: without normals, clients MUST calculate flat normals and ignore the tangents.
    shade_flat(mesh, normal_mapped);
  } else if (size_t bad = repair_normals(mesh)) {
    context.warn(where + ".attributes.NORMAL: " + std::to_string(bad) + " zero-length normals recomputed");
  }
  if (mesh.tangents.empty() && needs_tangents) {
    if (mesh.texcoords0.empty())
      context.warn(where + (normal_maps ? ": normal map" : ": anisotropic material") +
                   " without TEXCOORD_0; tangents cannot be generated");
    else
      generate_tangents(mesh);
  }
}

// The primitive as a MeshDesc, deformed by `pose`; false when it holds no triangles (skipped
// with a warning) or is made of points or lines (appended to `strokes`, in object space).
bool convert_primitive(GltfContext& context, const tinygltf::Primitive& primitive, const std::string& where,
                       const MeshPose& pose, MeshDesc& mesh, std::vector<StrokeDesc>& strokes) {
  bool stroked = primitive.mode >= TINYGLTF_MODE_POINTS && primitive.mode <= TINYGLTF_MODE_LINE_STRIP;
  if (primitive.mode > TINYGLTF_MODE_TRIANGLE_FAN || primitive.mode < 0)
    context.fail(where + ".mode", "unknown primitive mode " + std::to_string(primitive.mode));
  if (!primitive.attributes.count("POSITION")) context.fail(where + ".attributes", "no POSITION attribute");
  using T = std::vector<int>;
  int components = 0;
  std::vector<float> xyz = read_accessor_floats(context, primitive.attributes.at("POSITION"),
                                                where + ".attributes.POSITION", T{TINYGLTF_TYPE_VEC3}, components);
  check_finite(context, xyz, 3, where + ".attributes.POSITION");
  size_t count = xyz.size() / 3;
  context.charge(count * sizeof(vec3), where + ".attributes.POSITION");
  mesh.positions.resize(count);
  for (size_t i = 0; i < count; ++i) mesh.positions[i] = {xyz[i * 3], xyz[i * 3 + 1], xyz[i * 3 + 2]};
  mesh.normals = attribute<vec3, 3>(context, primitive, "NORMAL", T{TINYGLTF_TYPE_VEC3}, count, where);
  mesh.tangents = attribute<vec4, 4>(context, primitive, "TANGENT", T{TINYGLTF_TYPE_VEC4}, count, where);
  mesh.texcoords0 = attribute<vec2, 2>(context, primitive, "TEXCOORD_0", T{TINYGLTF_TYPE_VEC2}, count, where);
  mesh.texcoords1 = attribute<vec2, 2>(context, primitive, "TEXCOORD_1", T{TINYGLTF_TYPE_VEC2}, count, where);
  mesh.colors = attribute<vec4, 4>(context, primitive, "COLOR_0", T{TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, count,
                                   where);
  // Deformed before anything is derived from the vertices (triangles dropped, flat shading, tangents).
  apply_morph_targets(context, primitive, pose.weights, mesh, where);
  if (!pose.joint_matrices.empty()) apply_skin(context, primitive, pose.joint_matrices, mesh, where);
  std::vector<uint32_t> order = vertex_order(context, primitive, count, where);
  if (stroked) {
    int material = scene_material(context, variant_material(context, primitive, context.variant, where),
                                  where + ".material");
    add_primitive_stroke(context, primitive.mode, mesh, order, material, where, strokes);
    return false;
  }
  // A strip or a fan lists each triangle's three corners again.
  context.charge(saturating_multiply(order.size(), primitive.mode == TINYGLTF_MODE_TRIANGLES ? 4 : 12), where);
  mesh.indices = triangles_of(primitive.mode, order);
  mesh.material = scene_material(context, variant_material(context, primitive, context.variant, where),
                                 where + ".material");
  context.scene.degenerate_triangles_dropped += drop_degenerate_triangles(mesh);
  if (mesh.indices.empty()) {
    context.warn(where + ": no triangles left; primitive skipped");
    return false;
  }
  fill_shading_frames(context, mesh, !mesh.normals.empty(), where);
  return true;
}

}  // namespace

std::vector<int> convert_mesh(GltfContext& context, size_t m, const MeshPose& pose, const std::string& suffix,
                              std::vector<StrokeDesc>& strokes) {
  const tinygltf::Mesh& source = context.model.meshes[m];
  std::vector<int> parts;
  for (size_t p = 0; p < source.primitives.size(); ++p) {
    MeshDesc mesh;
    mesh.name = source.name.empty() ? element("meshes", m) : source.name;
    if (source.primitives.size() > 1) mesh.name += std::string("/").append(std::to_string(p));
    mesh.name += suffix;
    std::string where = element("meshes", m) + "." + element("primitives", p);
    if (!convert_primitive(context, source.primitives[p], where, pose, mesh, strokes)) continue;
    parts.push_back(int(context.scene.meshes.size()));
    context.scene.meshes.push_back(std::move(mesh));
  }
  return parts;
}

void convert_meshes(GltfContext& context) {
  const auto& model = context.model;
  context.mesh_parts.assign(model.meshes.size(), {});
  context.mesh_strokes.assign(model.meshes.size(), {});
  for (size_t m = 0; m < model.meshes.size(); ++m) {
    MeshPose pose;
    pose.weights = model.meshes[m].weights;
    context.mesh_parts[m] = convert_mesh(context, m, pose, "", context.mesh_strokes[m]);
  }
}

int mirrored_mesh(GltfContext& context, int mesh) {
  auto it = context.mirrored_meshes.find(mesh);
  if (it != context.mirrored_meshes.end()) return it->second;
  context.charge(mesh_bytes(context.scene.meshes[mesh]), context.scene.meshes[mesh].name + " (mirrored)");
  MeshDesc copy = context.scene.meshes[mesh];
  copy.name += " (mirrored)";
  for (size_t t = 0; t + 2 < copy.indices.size(); t += 3) std::swap(copy.indices[t + 1], copy.indices[t + 2]);
  // A mirror flips the bitangent too: keep the normal map's handedness.
  for (vec4& tangent : copy.tangents) tangent.w = -tangent.w;
  int index = int(context.scene.meshes.size());
  context.scene.meshes.push_back(std::move(copy));
  context.mirrored_meshes[mesh] = index;
  return index;
}

}  // namespace radiant
