// A bounding volume hierarchy over the lights that have a position, for choosing one in
// proportion to its estimated contribution at a shading point (pbrt-v4's BVHLightSampler,
// Cycles' light tree): each step down picks a child by its importance, and the probability of
// a light is the product of those choices along its path from the root.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "lights/importance8.h"
#include "math/lane_isa.h"

namespace radiant {

// A node of the light BVH: up to eight children side by side, so that one pass of eight-wide
// arithmetic rates them all (importance8). A lane is an interior child (child >= 0, the node's
// index), a leaf (child < 0, the light's slot is ~child) or empty (intensity 0, never chosen).
struct LightBvhNode {
  ImportanceBounds8 bounds;
  std::array<int, light_node_width> child = {};
  int parent = -1;       // -1 for the root
  int parent_lane = -1;  // the lane of the parent that leads here
};

// Where a light sits in the tree: the node and lane of its leaf.
struct LightBvhLeaf {
  int node = -1, lane = -1;
};

struct LightBvh {
  std::vector<LightBvhNode> nodes;           // root first
  std::vector<LightBvhLeaf> leaf_of_light;   // per light-table slot; node -1 outside the tree
  bool empty() const { return nodes.empty(); }
};

// A light of the tree to put in: its slot in the light table and its bounds.
struct BoundedLight {
  int slot = 0;
  LightBounds bounds;
};

// The most nodes a tree of `lights` lights can have (build_light_bvh reserves them up front).
uint64_t light_bvh_nodes_at_most(uint64_t lights);

// Bytes build_light_bvh needs for `lights` lights out of `slots` table slots (tree and scratch),
// for charging the memory budget first.
uint64_t light_bvh_bytes(uint64_t lights, uint64_t slots);

// Builds the tree over `lights` (those of intensity 0 are left out: they are never chosen), split
// by pbrt-v4's cost of position and orientation; `slots` sizes leaf_of_light.
LightBvh build_light_bvh(std::vector<BoundedLight> lights, size_t slots);

// Chooses a light for point `p` with shading normal `n` (zero in a medium) from u in [0,1):
// sets its table slot and the probability of choosing it (the probabilities of all lights sum to
// one at every point). False only for an empty tree. `isa` only says how the ratings are worked
// out (lane_isa.h); every choice gives the same bits.
bool sample_light_bvh(const LightBvh& bvh, vec3 p, vec3 n, float u, int& slot, float& probability,
                      LaneIsa isa = LaneIsa::best);

// sample_light_bvh for `count` points at once (p[k], n[k], u[k]), with the same slots and
// probabilities to the bit; probability[k] is 0 where none was chosen. The descents run
// interleaved: each is a chain of dependent steps, and one's steps fill the others' waits.
void sample_light_bvh_many(const LightBvh& bvh, const vec3* p, const vec3* n, const float* u, int count, int* slot,
                           float* probability, LaneIsa isa = LaneIsa::best);

// The probability that sample_light_bvh chooses table slot `slot` at (p, n), found by walking
// from its leaf to the root; 0 for a slot outside the tree.
float light_bvh_probability(const LightBvh& bvh, vec3 p, vec3 n, int slot, LaneIsa isa = LaneIsa::best);

}  // namespace radiant
