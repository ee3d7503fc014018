#include "scene/scene_motion.h"

#include <cstring>

namespace radiant {

namespace {

template <typename T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}
bool same_positions(const std::vector<vec3>& a, const std::vector<vec3>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(vec3)) == 0);
}
bool same_pose(const CameraPose& a, const CameraPose& b) {
  return same_bits(a.position, b.position) && same_bits(a.forward, b.forward) && same_bits(a.up, b.up);
}

// The scene at each step must be the same scene posed differently; anything else (a node a
// morph target switched off, a camera gained) keeps the rendered time's still pose.
bool same_layout(const SceneDesc& a, const SceneDesc& b) {
  if (a.instances.size() != b.instances.size() || a.meshes.size() != b.meshes.size() || a.cameras.size() != b.cameras.size())
    return false;
  for (size_t i = 0; i < a.instances.size(); ++i)
    if (a.instances[i].mesh != b.instances[i].mesh) return false;
  for (size_t m = 0; m < a.meshes.size(); ++m)
    if (a.meshes[m].positions.size() != b.meshes[m].positions.size()) return false;
  return true;
}

void keep_what_moves(SceneDesc& scene, const std::vector<SceneDesc>& steps) {
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    bool moves = false;
    for (const SceneDesc& step : steps) moves |= !same_bits(step.instances[i].transform, steps[0].instances[i].transform);
    if (!moves) continue;
    for (const SceneDesc& step : steps) scene.instances[i].motion.push_back(step.instances[i].transform);
  }
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    bool moves = false;
    for (const SceneDesc& step : steps) moves |= !same_positions(step.meshes[m].positions, steps[0].meshes[m].positions);
    if (!moves) continue;
    for (const SceneDesc& step : steps) scene.meshes[m].motion_positions.push_back(step.meshes[m].positions);
  }
  for (size_t c = 0; c < scene.cameras.size(); ++c) {
    auto pose = [&](const SceneDesc& step) {
      const CameraDesc& camera = step.cameras[c];
      return CameraPose{camera.position, camera.forward, camera.up};
    };
    bool moves = false;
    for (const SceneDesc& step : steps) moves |= !same_pose(pose(step), pose(steps[0]));
    if (!moves) continue;
    for (const SceneDesc& step : steps) scene.cameras[c].motion.push_back(pose(step));
  }
}

}  // namespace

MotionCounts count_motion(const SceneDesc& scene) {
  MotionCounts counts;
  for (const InstanceDesc& instance : scene.instances) counts.instances += !instance.motion.empty();
  for (const MeshDesc& mesh : scene.meshes) counts.meshes += !mesh.motion_positions.empty();
  for (const CameraDesc& camera : scene.cameras) counts.cameras += !camera.motion.empty();
  return counts;
}

std::string describe_motion(const MotionCounts& counts) {
  std::string text;
  auto add = [&](size_t n, const char* what) {
    if (n == 0) return;
    text += (text.empty() ? "" : ", ") + std::to_string(n) + " " + what;
  };
  add(counts.instances, "moving instance(s)");
  add(counts.meshes, "deforming mesh(es)");
  add(counts.cameras, "moving camera(s)");
  return text + " while the shutter is open";
}

bool add_motion_steps(SceneDesc& scene, const std::vector<SceneDesc>& steps) {
  if (steps.size() < 2 || steps.size() > size_t(max_motion_steps)) return false;
  for (const SceneDesc& step : steps)
    if (!same_layout(scene, step)) return false;
  keep_what_moves(scene, steps);
  return true;
}

void drop_motion(SceneDesc& scene) {
  for (InstanceDesc& instance : scene.instances) instance.motion.clear();
  for (MeshDesc& mesh : scene.meshes) mesh.motion_positions.clear();
  for (CameraDesc& camera : scene.cameras) camera.motion.clear();
}

}  // namespace radiant
