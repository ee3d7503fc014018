// The path integrator's sample dimensions: where each vertex's random numbers lie, and the
// numbers a batch draws ahead for a vertex (VertexDraws).
#pragma once

#include <cstdint>

#include "math/vec.h"

namespace radiant {

// Internal to the path integrator: included by path.cpp alone.
namespace {

// Sample dimensions: 0-1 the pixel, then a fixed block per path vertex, so that switching an
// effect off never shifts the random numbers the others use.
constexpr uint32_t dimensions_per_vertex = 10;
enum VertexDimension : uint32_t {
  light_choice = 0, light_point = 1, lobe_choice = 3, bsdf_direction = 4, roulette = 6, alpha_choice = 7,
  environment_choice = 8, dispersion_channel = 9
};
constexpr uint32_t dimension(int depth, VertexDimension d) { return 2 + uint32_t(depth) * dimensions_per_vertex + d; }
constexpr int roulette_start_depth = 3;

// A vertex's random numbers drawn ahead, for a whole batch at once (draw_sample_lanes): the values
// the vertex would draw itself, to the bit (a 1D value is the first of its dimension's pair).
// Those a scene cannot use are not drawn (`has`); run() draws each when it needs it.
struct VertexDraws {
  vec2 direction;      // bsdf_direction
  vec3 cosine;         // sample_cosine_hemisphere(direction), drawn with it
  vec2 light_point;    // light_point
  float light_choice;  // light_choice
  float lobe_choice;   // lobe_choice
  float roulette;      // roulette, of the next vertex (the path's depth + 1; used from its start depth)
  uint32_t drawn = 0;  // the dimensions drawn: a bit (1 << VertexDimension) each
  bool lobe_choice_used = false;  // set by the vertex: whether its BSDF chose a lobe
  // The light chosen ahead by the light BVH, for all of a stage's paths together
  // (choose_lights_ahead): when `light_chosen`, the choice the vertex would make itself, made
  // (`light_found`) or not.
  bool light_chosen = false, light_found = false;
  uint32_t light_slot;
  float light_probability;

  bool has(VertexDimension d) const { return drawn & (1u << d); }
};

}  // namespace

}  // namespace radiant
