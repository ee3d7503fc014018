#include "scene/scene_changes.h"

#include <algorithm>
#include <cstring>

#include "scene/scene_motion.h"

namespace radiant {

namespace {

// Bit-for-bit equality: a value that rounds the same but differs in sign or NaN payload changed.
template <typename T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

template <typename T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool alpha_masked(const SceneDesc& scene, const MeshDesc& mesh) {
  return mesh.material >= 0 && scene.materials[mesh.material].alpha_mode == AlphaMode::mask;
}

bool single_sided(const SceneDesc& scene, const MeshDesc& mesh) {
  return mesh.material >= 0 && !scene.materials[mesh.material].double_sided;
}

bool same_shape(const ShapeDesc& a, const ShapeDesc& b) {
  return a.kind == b.kind && a.material == b.material && same_bits(a.center, b.center) && same_bits(a.axis, b.axis) &&
         same_bits(a.radius, b.radius) && same_bits(a.height, b.height);
}

}  // namespace

bool SceneChanges::any() const {
  auto set = [](char c) { return c != 0; };
  return shapes_changed || std::any_of(moved_instances.begin(), moved_instances.end(), set) ||
         std::any_of(deformed_meshes.begin(), deformed_meshes.end(), set);
}

std::optional<SceneChanges> scene_changes(const SceneDesc& before, const SceneDesc& after) {
  if (before.meshes.size() != after.meshes.size() || before.instances.size() != after.instances.size() ||
      before.shapes.size() != after.shapes.size() || !before.strokes.empty() || !after.strokes.empty() ||
      count_motion(before).any() || count_motion(after).any())  // motion steps: built anew
    return std::nullopt;
  SceneChanges changes;
  changes.deformed_meshes.resize(after.meshes.size());
  for (size_t m = 0; m < after.meshes.size(); ++m) {
    const MeshDesc &a = before.meshes[m], &b = after.meshes[m];
    if (a.positions.size() != b.positions.size() || !same_bits(a.indices, b.indices) ||
        alpha_masked(before, a) != alpha_masked(after, b) || single_sided(before, a) != single_sided(after, b))
      return std::nullopt;
    changes.deformed_meshes[m] = !same_bits(a.positions, b.positions);
  }
  changes.moved_instances.resize(after.instances.size());
  for (size_t i = 0; i < after.instances.size(); ++i) {
    const InstanceDesc &a = before.instances[i], &b = after.instances[i];
    if (a.mesh != b.mesh) return std::nullopt;
    changes.moved_instances[i] = !same_bits(a.transform, b.transform);
  }
  for (size_t s = 0; s < after.shapes.size(); ++s)
    changes.shapes_changed = changes.shapes_changed || !same_shape(before.shapes[s], after.shapes[s]);
  return changes;
}

}  // namespace radiant
