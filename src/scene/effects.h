// The effects a scene calls for, derived from its content at load, each with its reason.
// Integrators are compiled for a few effect sets and run the smallest one that covers the scene.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene_desc.h"

namespace radiant {

// One bit per effect an integrator can switch off.
enum Effect : uint32_t {
  effect_direct_delta = 1u << 0,         // point, spot and directional lights
  effect_ambient = 1u << 1,              // ambient light (Whitted only)
  effect_shadows = 1u << 2,              // shadow rays towards lights
  effect_transparent_shadows = 1u << 3,  // shadows attenuated by transmissive occluders
  effect_reflection = 1u << 4,           // mirror reflection (Whitted kr, path delta reflection)
  effect_refraction = 1u << 5,           // transmission through surfaces
  effect_emission = 1u << 6,             // emissive surfaces seen or sampled as area lights
  effect_environment = 1u << 7,          // light from the background (uniform or map)
  effect_textures = 1u << 8,             // texture fetches
  effect_normal_maps = 1u << 9,          // tangent-space normal perturbation
  effect_alpha = 1u << 10,               // alpha cut-outs and blending
  effect_indirect = 1u << 11,            // indirect (global) illumination (path tracer)
  effect_absorption = 1u << 12,          // Beer-Lambert absorption inside transmissive volumes (path tracer)
  effect_single_sided = 1u << 13,        // camera rays pass through single-sided materials' back faces
  effect_motion_blur = 1u << 14,         // camera rays spread over the shutter's time (scene/motion_steps.h)
};
constexpr uint32_t effect_all = (1u << 15) - 1;

struct EffectInfo {
  Effect effect;
  const char* name;  // as used by --effects and `radiant info`
};
const std::vector<EffectInfo>& effect_catalog();

struct EffectSet {
  uint32_t mask = 0;
  std::vector<std::string> reasons;  // one per set bit, in catalog order: "shadows: 3 lights..."
  bool has(Effect e) const { return (mask & e) != 0; }
};

// What the scene calls for (independent of the integrator).
EffectSet analyze_effects(const SceneDesc& scene);

// Applies an --effects list ("-shadows,-indirect", "all", "+environment") to `mask`.
// Throws std::invalid_argument naming an unknown effect.
uint32_t apply_effects_override(uint32_t mask, const std::string& list);

// Names of the set bits, comma-separated.
std::string effect_names(uint32_t mask);

}  // namespace radiant
