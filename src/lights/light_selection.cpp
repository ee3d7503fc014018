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

void choose_lights_by_bvh_many(const LightTable& lights, const vec3* p, const vec3* n, const float* u, int count,
                               LightChoice* choice, bool* found) {
  const Distribution1D& top = lights.infinite_selection;
  // The points whose choice falls on the tree, descended together a group at a time.
  constexpr int group = 16;
  vec3 tree_p[group], tree_n[group];
  float tree_u[group], in_tree[group];
  int tree_slot[group], waiting[group], waiting_count = 0;
  size_t tree_entry = top.empty() ? 0 : top.size() - 1;
  auto descend_waiting = [&] {
    sample_light_bvh_many(lights.bvh, tree_p, tree_n, tree_u, waiting_count, tree_slot, in_tree);
    for (int j = 0; j < waiting_count; ++j) {
      LightChoice& c = choice[waiting[j]];
      c.slot = size_t(tree_slot[j]);
      c.probability = top.pmf[tree_entry] * in_tree[j];
      found[waiting[j]] = in_tree[j] > 0 && c.probability > 0;
    }
    waiting_count = 0;
  };
  for (int k = 0; k < count; ++k) {
    found[k] = false;
    if (top.empty()) continue;
    float u_tree = u[k];
    size_t entry = top.size() > 1 ? sample_discrete(top, u[k], &u_tree) : 0;
    if (entry < lights.infinite_lights.size()) {
      choice[k].slot = size_t(lights.infinite_lights[entry]);
      choice[k].probability = top.pmf[entry];
      found[k] = true;
      continue;
    }
    tree_p[waiting_count] = p[k], tree_n[waiting_count] = n[k], tree_u[waiting_count] = u_tree;
    waiting[waiting_count++] = k;
    if (waiting_count == group) descend_waiting();
  }
  if (waiting_count > 0) descend_waiting();
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
