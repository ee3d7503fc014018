#include "fuzz_targets.h"

namespace radiant::fuzz {

const std::vector<FuzzTarget>& fuzz_targets() {
  static const std::vector<FuzzTarget> targets = {
      {"scene", run_scene_target}, {"gltf", run_gltf_target},   {"render", run_render_target},
      {"obj", run_obj_target},     {"batch", run_batch_target}, {"image", run_image_target},
      {"page", run_page_target}};
  return targets;
}

const FuzzTarget* find_fuzz_target(const std::string& name) {
  for (const FuzzTarget& target : fuzz_targets())
    if (name == target.name) return &target;
  return nullptr;
}

}  // namespace radiant::fuzz
