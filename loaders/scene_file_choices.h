// What a scene file offers to choose from besides cameras and lights, for `radiant info`.
#pragma once

#include <string>
#include <vector>

namespace radiant {

struct AnimationSummary {
  std::string name;
  double seconds = 0;  // the last key time of its channels
};
struct SceneFileChoices {
  std::vector<AnimationSummary> animations;   // --animation, --time, --frame
  std::vector<std::string> material_variants;  // --variant (KHR_materials_variants)
};

}  // namespace radiant
