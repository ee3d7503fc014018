#include "gltf/gltf_nodes.h"

#include <cmath>

#include "gltf/gltf_lights_cameras.h"
#include "gltf/gltf_meshes.h"

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
  q = {q.x / q_length, q.y / q_length, q.z / q_length, q.w / q_length};
  return translation(t) * rotation_quaternion(q) * scaling(s);
}

namespace {

// What one node contributes, once its world transform is known.
void place_node(GltfContext& context, const tinygltf::Node& node, const mat4& world, const std::string& where) {
  if (node.mesh >= 0) {
    check_index(context, node.mesh, context.model.meshes.size(), where + ".mesh", "mesh");
    mat4 inverse;
    if (!inverse_affine(world, inverse)) {
      // glTF allows a zero scale (it hides a node); a flattened mesh has no area to render.
      context.warn(where + ": singular transform (a zero scale): the mesh is not rendered");
    } else {
      bool mirrors = determinant3(world) < 0;
      for (int part : context.mesh_parts[node.mesh]) {
        InstanceDesc instance;
        instance.mesh = mirrors ? mirrored_mesh(context, part) : part;
        instance.transform = world;
        instance.name = node.name;
        context.scene.instances.push_back(instance);
      }
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

enum class Visit { not_yet, on_path, done };

struct Frame {
  int node;
  mat4 world;
  size_t next_child = 0;
};

// Depth first with an explicit stack: deep hierarchies cannot overflow, cycles are reported.
void walk(GltfContext& context, int root, std::vector<Visit>& visits, const std::string& root_where) {
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
    place_node(context, nodes[node], world, node_where);
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
  const std::vector<int>& roots = model.scenes[scene].nodes;
  for (size_t i = 0; i < roots.size(); ++i)
    walk(context, roots[i], visits, element("scenes", size_t(scene)) + "." + element("nodes", i));
}

}  // namespace radiant
