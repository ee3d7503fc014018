#include "lights/light_selection.h"

namespace radiant {

bool choose_light_by_bvh(const LightTable& lights, vec3 p, vec3 n, float u, LightChoice& choice) {
  const Distribution1D& top = lights.infinite_selection;
  if (top.empty()) return false;
  float u_tree = u;
  size_t entry = top.size() > 1 ? sample_discrete(top, u, &u_tree) : 0;
  if (entry < lights.infinite_lights.size()) {
    choice.slot = size_t(lights.infinite_lights[entry]);
    choice.probability = top.pmf[entry];
    return true;
  }
  int slot = -1;
  float in_tree = 0;
  if (!sample_light_bvh(lights.bvh, p, n, u_tree, slot, in_tree)) return false;
  choice.slot = size_t(slot);
  choice.probability = top.pmf[entry] * in_tree;
  return choice.probability > 0;
}

float light_choice_probability_by_bvh(const LightTable& lights, vec3 p, vec3 n, size_t slot) {
  const Distribution1D& top = lights.infinite_selection;
  if (top.empty()) return 0;
  // Few lights lie at infinity (directional lights and one environment): a search is enough.
  for (size_t entry = 0; entry < lights.infinite_lights.size(); ++entry)
    if (size_t(lights.infinite_lights[entry]) == slot) return top.pmf[entry];
  return top.pmf.back() * light_bvh_probability(lights.bvh, p, n, int(slot));
}

}  // namespace radiant
