// Choosing the one light a path vertex samples, and the probability of that choice, which MIS
// needs again when a BSDF-sampled ray hits the same light: both go through here so that the two
// can never disagree.
#pragma once

#include "lights/light_table.h"

namespace radiant {

struct LightChoice {
  size_t slot = 0;          // in [delta lights..., area lights..., environment]
  float probability = 0;
};

bool choose_light_by_bvh(const LightTable& lights, vec3 p, vec3 n, float u, LightChoice& choice);
float light_choice_probability_by_bvh(const LightTable& lights, vec3 p, vec3 n, size_t slot);

// choose_light_by_bvh at `count` points at once (p[k], n[k], u[k]), the same choices to the bit;
// found[k] is its return value. The tree's descents run interleaved (sample_light_bvh_many).
void choose_lights_by_bvh_many(const LightTable& lights, const vec3* p, const vec3* n, const float* u, int count,
                               LightChoice* choice, bool* found);

// Whether choose_light draws a number (for drawing it ahead).
inline bool light_choice_draws(const LightTable& lights) {
  return lights.sampler == LightSampler::bvh || lights.selection.size() > 1;
}

// Chooses a light for point `p` with shading normal `n`, calling `draw_u` for a number in [0,1)
// only when there is a choice to make (one light under power sampling has none); false when
// none can be chosen. Power sampling ignores p and n and stays inline: a scene with few lights
// pays one branch for the BVH.
template <class DrawU>
inline bool choose_light(const LightTable& lights, vec3 p, vec3 n, DrawU draw_u, LightChoice& choice) {
  if (lights.sampler == LightSampler::bvh) return choose_light_by_bvh(lights, p, n, draw_u(), choice);
  if (lights.selection.empty()) return false;
  choice.slot = light_choice_draws(lights) ? sample_discrete(lights.selection, draw_u()) : 0;
  choice.probability = lights.selection.pmf[choice.slot];
  return true;
}

// The probability that choose_light picks `slot` at (p, n).
inline float light_choice_probability(const LightTable& lights, vec3 p, vec3 n, size_t slot) {
  if (lights.sampler == LightSampler::bvh) return light_choice_probability_by_bvh(lights, p, n, slot);
  return lights.selection.pmf[slot];
}

}  // namespace radiant
