#include "gltf/gltf_nodes.h"

#include <cmath>
#include <map>
#include <set>

#include "gltf/gltf_accessors.h"
#include "gltf/gltf_instancing.h"
#include "gltf/gltf_lights_cameras.h"
#include "gltf/gltf_meshes.h"
#include "gltf/gltf_strokes.h"
#include "scene/scene_memory.h"

namespace radiant {

static vec3 triple(const std::vector<double>& v, vec3 fallback) {
  return v.size() == 3 ? vec3{float(v[0]), float(v[1]), float(v[2])} : fallback;
}

mat4 local_transform(const GltfContext& context, const tinygltf::Node& node, const std::string& where) {
  mat4 local;
  if (node.matrix.size() == 16) {
    for (int row = 0; row < 4; ++row)
      for (int column = 0; column < 4; ++column) local.m[row][column] = float(node.matrix[column * 4 + row]);
    if (!is_finite(local)) context.fail(where + ".matrix", "non-finite value");
    return local;
  }
  vec3 t = triple(node.translation, {0, 0, 0}), s = triple(node.scale, {1, 1, 1});
  vec4 q = {0, 0, 0, 1};
  if (node.rotation.size() == 4)
    q = {float(node.rotation[0]), float(node.rotation[1]), float(node.rotation[2]), float(node.rotation[3])};
  float q_length = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  if (!is_finite(t)) context.fail(where + ".translation", "non-finite value");
  if (!is_finite(s)) context.fail(where + ".scale", "non-finite value");
  if (!std::isfinite(q_length) || q_length == 0) context.fail(where + ".rotation", "not a rotation quaternion");
  return compose_trs(t, q, s);
}

namespace {

// What the walk has learned for the skins: the joints' world transforms, and the skinned nodes,
// placed once every joint's transform is known.
struct PlacedNodes {
  std::set<int> joints;             // every node a skin names
  std::map<int, mat4> joint_world;  // those the walk has placed
  std::vector<std::pair<int, std::string>> skinned;  // node, its JSON path
};

// A mesh's pieces placed by one transform: its triangle parts and its points and lines.
struct MeshPieces {
  std::vector<int> parts;
  std::vector<StrokeDesc> strokes;
};

void add_instances(GltfContext& context, const MeshPieces& pieces, const mat4& world, const std::string& name) {
  place_strokes(context, pieces.strokes, world);
  const std::vector<int>& parts = pieces.parts;
  bool mirrors = determinant3(world) < 0;
  for (int part : parts) {
    InstanceDesc instance;
    instance.mesh = mirrors ? mirrored_mesh(context, part) : part;
    instance.transform = world;
    instance.name = name;
    context.scene.instances.push_back(instance);
  }
}

// EXT_mesh_gpu_instancing: the node's mesh once per instance, at world × the instance's T·R·S.
// The instances are charged before the scene's array grows for them.
void add_gpu_instances(GltfContext& context, const MeshPieces& pieces, const mat4& world,
                       const tinygltf::Node& node, const tinygltf::Value& extension, const std::string& where) {
  GpuInstances instances = read_gpu_instances(context, extension, where);
  InstanceDesc sample;
  sample.name = node.name;
  uint64_t placed = saturating_multiply(instances.count, pieces.parts.size());
  context.charge(saturating_multiply(placed, instance_bytes(sample)), where);
  std::vector<InstanceDesc>& scene_instances = context.scene.instances;
  scene_instances.reserve(scene_instances.size() + placed);
  size_t hidden = 0;
  for (size_t i = 0; i < instances.count; ++i) {
    mat4 transform = world * gpu_instance_transform(instances, i), inverse;
    // A zero scale hides an instance, as it hides a node.
    if (!is_finite(transform) || !inverse_affine(transform, inverse) || !inverse_survives_float(transform)) {
      ++hidden;
      continue;
    }
    add_instances(context, pieces, transform, node.name);
  }
  if (hidden)
    context.warn(where + ": " + std::to_string(hidden) + " of " + std::to_string(instances.count) +
                 " instances have a singular transform (a zero scale): they are not rendered");
}

// What one node contributes, once its world transform is known.
void place_node(GltfContext& context, PlacedNodes& placed, int index, const mat4& world, const std::string& where) {
  const tinygltf::Node& node = context.model.nodes[size_t(index)];
  if (placed.joints.count(index)) placed.joint_world[index] = world;
  if (node.mesh >= 0) {
    check_index(context, node.mesh, context.model.meshes.size(), where + ".mesh", "mesh");
    mat4 inverse;
    if (node.skin >= 0) {
      placed.skinned.push_back({index, where});  // its joints may come later in the walk
    } else if (!inverse_affine(world, inverse)) {
      // glTF allows a zero scale (it hides a node); a flattened mesh has no area to render.
      context.warn(where + ": singular transform (a zero scale): the mesh is not rendered");
    } else if (!inverse_survives_float(world)) {
      // A scale animated towards zero passes through such transforms; the mesh is a speck then.
      context.warn(where + ": transform too close to singular to invert in single precision: the mesh is not rendered");
    } else {
      MeshPieces pieces{context.mesh_parts[node.mesh], context.mesh_strokes[node.mesh]};
      if (!node.weights.empty() && node.weights != context.model.meshes[size_t(node.mesh)].weights) {
        MeshPose pose;
        pose.weights = node.weights;
        pieces.strokes.clear();
        pieces.parts = convert_mesh(context, size_t(node.mesh), pose, " (" + where + " weights)", pieces.strokes);
      }
      auto instancing = node.extensions.find("EXT_mesh_gpu_instancing");
      if (instancing != node.extensions.end())
        add_gpu_instances(context, pieces, world, node, instancing->second, where + ".extensions.EXT_mesh_gpu_instancing");
      else
        add_instances(context, pieces, world, node.name);
    }
  }
  if (node.camera >= 0) add_camera(context, node.camera, world, node.name, where + ".camera");
  auto light = node.extensions.find("KHR_lights_punctual");
  if (light != node.extensions.end() && light->second.Has("light")) {
    std::string light_where = where + ".extensions.KHR_lights_punctual.light";
    add_light(context, index_value(context, light->second.Get("light"), context.model.lights.size(), light_where, "light"),
              world, light_where);
  }
}

// Each joint's world transform times its inverse bind matrix (identity when the skin has none).
std::vector<mat4> joint_matrices(const GltfContext& context, const PlacedNodes& placed, int skin_index,
                                 const std::string& where) {
  check_index(context, skin_index, context.model.skins.size(), where, "skin");
  const tinygltf::Skin& skin = context.model.skins[size_t(skin_index)];
  std::string skin_where = element("skins", size_t(skin_index));
  std::vector<float> inverse_binds;
  if (skin.inverseBindMatrices >= 0) {
    int components = 0;
    inverse_binds = read_accessor_floats(context, skin.inverseBindMatrices, skin_where + ".inverseBindMatrices",
                                         {TINYGLTF_TYPE_MAT4}, components);
    if (inverse_binds.size() / 16 < skin.joints.size())
      context.fail(skin_where + ".inverseBindMatrices", std::to_string(inverse_binds.size() / 16) + " matrices for " +
                                                            std::to_string(skin.joints.size()) + " joints");
  }
  std::vector<mat4> matrices;
  for (size_t j = 0; j < skin.joints.size(); ++j) {
    std::string joint_where = skin_where + "." + element("joints", j);
    int joint = skin.joints[j];
    check_index(context, joint, context.model.nodes.size(), joint_where, "node");
    auto joint_world = placed.joint_world.find(joint);
    if (joint_world == placed.joint_world.end())
      context.fail(joint_where, "node " + std::to_string(joint) + " is not in the rendered scene");
    mat4 inverse_bind;
    if (!inverse_binds.empty())
      for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 4; ++column) inverse_bind.m[row][column] = inverse_binds[j * 16 + column * 4 + row];
    if (!is_finite(inverse_bind)) context.fail(skin_where + ".inverseBindMatrices", "non-finite value");
    matrices.push_back(joint_world->second * inverse_bind);
  }
  return matrices;
}

// Skinned meshes are posed in world space from their joints (glTF ignores the node's own
// transform for them), placed by an identity instance. EXT_mesh_gpu_instancing does not say how
// it combines with skinning: each instance's transform places the posed mesh, as it would
// place it under an identity node, and a warning says so.
void place_skinned_nodes(GltfContext& context, const PlacedNodes& placed) {
  for (const auto& [index, where] : placed.skinned) {
    const tinygltf::Node& node = context.model.nodes[size_t(index)];
    MeshPose pose;
    pose.weights = node.weights.empty() ? context.model.meshes[size_t(node.mesh)].weights : node.weights;
    pose.joint_matrices = joint_matrices(context, placed, node.skin, where + ".skin");
    MeshPieces pieces;
    pieces.parts = convert_mesh(context, size_t(node.mesh), pose, " (" + where + " skinned)", pieces.strokes);
    auto instancing = node.extensions.find("EXT_mesh_gpu_instancing");
    if (instancing == node.extensions.end()) {
      add_instances(context, pieces, mat4{}, node.name);
      continue;
    }
    std::string instancing_where = where + ".extensions.EXT_mesh_gpu_instancing";
    context.warn(instancing_where + ": instancing a skinned mesh is not defined by the extension; each instance's "
                                    "transform places the posed mesh in world space");
    add_gpu_instances(context, pieces, mat4{}, node, instancing->second, instancing_where);
  }
}

enum class Visit { not_yet, on_path, done };

struct Frame {
  int node;
  mat4 world;
  size_t next_child = 0;
};

// Depth first with an explicit stack: deep hierarchies cannot overflow, cycles are reported.
void walk(GltfContext& context, PlacedNodes& placed, int root, std::vector<Visit>& visits,
          const std::string& root_where) {
  const auto& nodes = context.model.nodes;
  auto enter = [&](std::vector<Frame>& stack, int node, const mat4& parent, const std::string& where) {
    check_index(context, node, nodes.size(), where, "node");
    if (visits[node] == Visit::on_path)
      context.fail(where, "cycle in the node graph (node " + std::to_string(node) + " is its own ancestor)");
    if (visits[node] == Visit::done)
      context.fail(where, "node " + std::to_string(node) + " is reached twice (glTF nodes form trees)");
    visits[node] = Visit::on_path;
    std::string node_where = element("nodes", size_t(node));
    mat4 world = parent * local_transform(context, nodes[node], node_where);
    if (!is_finite(world)) context.fail(node_where, "non-finite world transform");
    place_node(context, placed, node, world, node_where);
    stack.push_back({node, world});
  };
  std::vector<Frame> stack;
  enter(stack, root, mat4{}, root_where);
  while (!stack.empty()) {
    Frame& top = stack.back();
    const std::vector<int>& children = nodes[top.node].children;
    if (top.next_child == children.size()) {
      visits[top.node] = Visit::done;
      stack.pop_back();
      continue;
    }
    size_t child = top.next_child++;
    std::string where = element("nodes", size_t(top.node)) + "." + element("children", child);
    mat4 world = top.world;  // `top` may move when the stack grows
    enter(stack, children[child], world, where);
  }
}

}  // namespace

void convert_nodes(GltfContext& context) {
  const auto& model = context.model;
  if (model.scenes.empty()) {
    context.warn("no scenes in the file");
    return;
  }
  int scene = context.options.gltf_scene >= 0 ? context.options.gltf_scene : std::max(model.defaultScene, 0);
  if (size_t(scene) >= model.scenes.size())
    throw LoadError(context.file + ": scene " + std::to_string(scene) + " out of range (" +
                    std::to_string(model.scenes.size()) + " scenes)");
  std::vector<Visit> visits(model.nodes.size(), Visit::not_yet);
  PlacedNodes placed;
  for (size_t i = 0; i < model.skins.size(); ++i) {
    // Two tree nodes and a matrix a joint (the JSON charge covers the skin's own arrays).
    context.charge(model.skins[i].joints.size() * (2 * 48 + sizeof(mat4)), element("skins", i) + ".joints");
    placed.joints.insert(model.skins[i].joints.begin(), model.skins[i].joints.end());
  }
  const std::vector<int>& roots = model.scenes[scene].nodes;
  for (size_t i = 0; i < roots.size(); ++i)
    walk(context, placed, roots[i], visits, element("scenes", size_t(scene)) + "." + element("nodes", i));
  place_skinned_nodes(context, placed);
}

}  // namespace radiant
