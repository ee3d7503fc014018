// The effect sets the integrators are compiled for, and choosing one once per render.
// Cheap effects (direct light, shadows, emission...) are always compiled in and switched at run
// time; the costly groups below are compiled in or out, giving 16 variants per integrator.
#pragma once

#include <array>
#include <cstdint>
#include <utility>

#include "scene/effects.h"

namespace radiant {

constexpr uint32_t effect_group_transparency =
    effect_transparent_shadows | effect_refraction | effect_alpha | effect_absorption;
constexpr uint32_t effect_group_textures = effect_textures | effect_normal_maps;
constexpr uint32_t effect_group_reflection = effect_reflection;
constexpr uint32_t effect_group_indirect = effect_indirect;
constexpr uint32_t effect_always_compiled =
    effect_all & ~(effect_group_transparency | effect_group_textures | effect_group_reflection | effect_group_indirect);
constexpr std::array<uint32_t, 4> effect_groups = {effect_group_transparency, effect_group_textures,
                                                   effect_group_reflection, effect_group_indirect};

constexpr uint32_t variant_mask(size_t index) {
  uint32_t mask = effect_always_compiled;
  for (size_t g = 0; g < effect_groups.size(); ++g)
    if (index & (size_t(1) << g)) mask |= effect_groups[g];
  return mask;
}

constexpr size_t variant_index(uint32_t needed) {
  size_t index = 0;
  for (size_t g = 0; g < effect_groups.size(); ++g)
    if (needed & effect_groups[g]) index |= size_t(1) << g;
  return index;
}

// The compiled effect set that serves `needed`.
constexpr uint32_t smallest_variant(uint32_t needed) { return variant_mask(variant_index(needed)); }

// True when effect `e` is compiled into variant E and switched on for this render.
template <uint32_t E>
constexpr bool enabled(uint32_t runtime_effects, Effect e) {
  return (E & e) != 0 && (runtime_effects & e) != 0;
}

namespace detail {
template <class Variants, template <uint32_t> class Impl, size_t... I>
constexpr Variants variant_table(std::index_sequence<I...>) {
  return {{{&Impl<variant_mask(I)>::run, &Impl<variant_mask(I)>::run_batch}...}};
}
}  // namespace detail

// `Impl<E>::run` and `Impl<E>::run_batch` compiled for every variant, as an `Entry` (an
// aggregate of the two function pointers); returns the one serving `needed`.
template <class Entry, template <uint32_t> class Impl>
Entry select_variant(uint32_t needed) {
  using Variants = std::array<Entry, size_t(1) << effect_groups.size()>;
  static constexpr Variants table =
      detail::variant_table<Variants, Impl>(std::make_index_sequence<size_t(1) << effect_groups.size()>{});
  return table[variant_index(needed)];
}

}  // namespace radiant
