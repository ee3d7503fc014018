#include "lights/light_bvh.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>

namespace radiant {

namespace {

constexpr int split_buckets = 12;
constexpr double below_one = 1.0 - 1e-12;  // a rescaled u stays in [0, 1) despite rounding

// pbrt-v4's cost of a group: brightness x orientation spread x surface area, with the area
// stretched when splitting along a short axis of the parent (thin slices are poor groups).
float group_cost(const LightBounds& group, vec3 parent_extent, int axis) {
  if (!(group.intensity > 0)) return 0;
  vec3 e = group.upper - group.lower;
  float area = 2 * (e.x * e.y + e.y * e.z + e.z * e.x);
  float stretch = max_component(parent_extent) / parent_extent[axis];
  return group.intensity * orientation_measure(group) * stretch * area;
}

// Which of the buckets along `axis`, from `low` over `span`, a light's centre falls in.
int bucket_of(const BoundedLight& light, int axis, float low, float span) {
  float c = (light.bounds.lower[axis] + light.bounds.upper[axis]) * 0.5f;
  return std::clamp(int(split_buckets * (c - low) / span), 0, split_buckets - 1);
}

// The split of lights[begin, end) with the lowest cost; end when none separates them.
using LightIterator = std::vector<BoundedLight>::iterator;
LightIterator partition_lights(LightIterator begin, LightIterator end, const LightBounds& all) {
  vec3 centroid_lower = begin->bounds.lower, centroid_upper = centroid_lower;
  for (auto it = begin; it != end; ++it) {
    vec3 c = (it->bounds.lower + it->bounds.upper) * 0.5f;
    centroid_lower = min(centroid_lower, c), centroid_upper = max(centroid_upper, c);
  }
  vec3 extent = all.upper - all.lower;
  float best_cost = std::numeric_limits<float>::infinity();
  int best_axis = -1, best_bucket = -1;
  for (int axis = 0; axis < 3; ++axis) {
    float low = centroid_lower[axis], span = centroid_upper[axis] - low;
    if (!(span > 0)) continue;
    std::array<LightBounds, split_buckets> buckets{};
    for (auto it = begin; it != end; ++it) {
      LightBounds& bucket = buckets[size_t(bucket_of(*it, axis, low, span))];
      bucket = merge(bucket, it->bounds);
    }
    // Every split's two sides from one sweep each way: merging is the build's dearest step.
    std::array<LightBounds, split_buckets> above_split{};  // [s]: buckets s + 1 and after
    for (int split = split_buckets - 2; split >= 0; --split)
      above_split[size_t(split)] = merge(above_split[size_t(split + 1)], buckets[size_t(split + 1)]);
    LightBounds below;
    for (int split = 0; split < split_buckets - 1; ++split) {
      below = merge(below, buckets[size_t(split)]);
      const LightBounds& above = above_split[size_t(split)];
      float cost = group_cost(below, extent, axis) + group_cost(above, extent, axis);
      if (cost < best_cost) best_cost = cost, best_axis = axis, best_bucket = split;
    }
  }
  if (best_axis < 0) return end;
  float low = centroid_lower[best_axis], span = centroid_upper[best_axis] - low;
  return std::partition(begin, end, [&](const BoundedLight& l) { return bucket_of(l, best_axis, low, span) <= best_bucket; });
}

// Lights [begin, end) waiting to become a node below `parent` while the binary tree is built.
struct LightRange {
  size_t begin, end;
  int parent;
};

// The binary tree the build makes first (pbrt-v4's), before it is collapsed to four-wide nodes.
struct BinaryNode {
  ImportanceBounds bounds;
  int second_child = -1;  // interior nodes: the first child is the next node
  int light = -1;         // leaves: the light's slot
  bool is_leaf() const { return light >= 0; }
};

// A binary interior node waiting to become a four-wide node, in lane `lane` of `parent`.
struct PendingNode {
  int binary, parent, lane;
};

std::vector<BinaryNode> build_binary_tree(std::vector<BoundedLight>& lights) {
  std::vector<BinaryNode> nodes;
  nodes.reserve(2 * lights.size() - 1);
  // Depth-first without recursion (a tree of many lights can be deep): a range is made a node
  // when taken from the stack; the first child is taken next, so it is always the next node.
  std::vector<LightRange> stack = {{0, lights.size(), -1}};
  while (!stack.empty()) {
    LightRange r = stack.back();
    stack.pop_back();
    int index = int(nodes.size());
    BinaryNode& node = nodes.emplace_back();
    if (r.parent >= 0 && r.parent + 1 != index) nodes[size_t(r.parent)].second_child = index;
    if (r.end - r.begin == 1) {
      node.bounds = importance_bounds(lights[r.begin].bounds);
      node.light = lights[r.begin].slot;
      continue;
    }
    LightBounds all;
    for (size_t i = r.begin; i < r.end; ++i) all = merge(all, lights[i].bounds);
    node.bounds = importance_bounds(all);
    auto begin = lights.begin() + ptrdiff_t(r.begin), end = lights.begin() + ptrdiff_t(r.end);
    auto middle = partition_lights(begin, end, all);
    if (middle == begin || middle == end) middle = begin + (end - begin) / 2;  // inseparable: halve
    size_t split = size_t(middle - lights.begin());
    stack.push_back({split, r.end, index});
    stack.push_back({r.begin, split, index});
  }
  return nodes;
}

// Each four-wide node takes a binary node's children, an interior child replaced by its own two:
// two levels of the binary tree per step down, rated in one four-wide pass.
void collapse_to_four_wide(const std::vector<BinaryNode>& binary, LightBvh& bvh) {
  std::vector<PendingNode> stack;
  auto put = [&](int node, int lane, int b) {
    const BinaryNode& from = binary[size_t(b)];
    set_lane(bvh.nodes[size_t(node)].bounds, lane, from.bounds);
    if (from.is_leaf()) {
      bvh.nodes[size_t(node)].child[size_t(lane)] = ~from.light;
      bvh.leaf_of_light[size_t(from.light)] = {node, lane};
    } else {
      stack.push_back({b, node, lane});
    }
  };
  bvh.nodes.emplace_back();
  if (binary[0].is_leaf()) {
    put(0, 0, 0);  // one light: a root with one lane
    return;
  }
  stack.push_back({0, -1, -1});
  while (!stack.empty()) {
    PendingNode pending = stack.back();
    stack.pop_back();
    int index = 0;
    if (pending.parent >= 0) {
      index = int(bvh.nodes.size());
      bvh.nodes.emplace_back();
      bvh.nodes[size_t(pending.parent)].child[size_t(pending.lane)] = index;
    }
    bvh.nodes[size_t(index)].parent = pending.parent;
    bvh.nodes[size_t(index)].parent_lane = pending.lane;
    int lane = 0;
    for (int child : {pending.binary + 1, binary[size_t(pending.binary)].second_child}) {
      if (binary[size_t(child)].is_leaf()) {
        put(index, lane++, child);
      } else {
        put(index, lane++, child + 1);
        put(index, lane++, binary[size_t(child)].second_child);
      }
    }
  }
}

// How a node shares the choice among its lanes at (p, n): by the children's importance; where
// the bounds rule all out, no light below can reach p and any choice is wasted (pbrt gives up
// there), so by intensity, which keeps every light's probability a distribution. Lane k's share
// of [0, total) is [start[k], start[k + 1]) (the last lane's ends at total); its probability
// rated[k] / total. One function for sampling and for the probability walk, so both agree.
// Inline: called, it kept p and n in memory across the call and returned the shares through the
// stack, on every step of the descent (2.7% of a many-lights render, thirtieth session).
struct LaneShares {
  float rated[4];
  float start[4];  // 0, rated[0], rated[0] + rated[1], ... + rated[2]
  float total;      // 0 only for a node that holds no light
};

[[gnu::always_inline]] inline LaneShares lane_shares(const LightBvhNode& node, vec3 p, vec3 n) {
  LaneShares shares;
  importance4(node.bounds, p, n, shares.rated);
  float low = shares.rated[0] + shares.rated[1], high = shares.rated[2] + shares.rated[3];
  shares.total = low + high;
  if (!(shares.total > 0)) {
    for (int lane = 0; lane < 4; ++lane) shares.rated[lane] = node.bounds.intensity[lane];
    low = shares.rated[0] + shares.rated[1], high = shares.rated[2] + shares.rated[3];
    shares.total = low + high;
  }
  shares.start[0] = 0, shares.start[1] = shares.rated[0], shares.start[2] = low, shares.start[3] = low + shares.rated[2];
  return shares;
}

double lane_probability(const LaneShares& shares, int lane) { return double(shares.rated[lane]) / shares.total; }

// A descent under way: the node it is at, u rescaled into that node's share, and the product of
// the choices so far.
struct Descent {
  int index;
  double remaining, chosen;
};

enum class Step { down, leaf, failed };

// One step of a descent at (p, n): the lane of the current node whose share holds `remaining`,
// then down to it; at a leaf `slot` is set. The single and the interleaved descents both take
// their steps here, so both choose the same light with the same probability, to the bit.
[[gnu::always_inline]] inline Step descend(const LightBvh& bvh, vec3 p, vec3 n, Descent& d, int& slot) {
  const LightBvhNode& node = bvh.nodes[size_t(d.index)];
  LaneShares shares = lane_shares(node, p, n);
  if (!(shares.total > 0)) return Step::failed;
  // The lane whose share holds `remaining`, found without branches: the lane is as random as u,
  // so a branch on it would be mispredicted a good part of the time, and the next node waits on
  // it. Counting the shares that start at or below the target gives a lane whose rating is
  // positive (a lane rated 0 starts where the next one does), except past the last rated lane,
  // where empty lanes and rounding beyond the total land: there the last rated lane takes it.
  // Only the next node waits on this: the divisions that rescale `remaining` and form the
  // probability run beside the next node's rating.
  double target = d.remaining * shares.total;
  float t = float(target);
  int lane = int(shares.start[1] <= t) + int(shares.start[2] <= t) + int(shares.start[3] <= t);
  unsigned rated = unsigned(shares.rated[0] > 0) | unsigned(shares.rated[1] > 0) << 1 |
                   unsigned(shares.rated[2] > 0) << 2 | unsigned(shares.rated[3] > 0) << 3;
  int last_rated = 31 - __builtin_clz(rated | 1u);
  lane = std::min(lane, last_rated);
  if (!(shares.rated[lane] > 0)) return Step::failed;  // an infinite or NaN rating
  double below = shares.start[lane];
  d.chosen *= lane_probability(shares, lane);
  d.remaining = std::clamp((target - below) / shares.rated[lane], 0.0, below_one);
  int child = node.child[size_t(lane)];
  if (child < 0) {
    slot = ~child;
    return Step::leaf;
  }
  d.index = child;
  return Step::down;
}

}  // namespace

uint64_t light_bvh_bytes(uint64_t lights, uint64_t slots) {
  uint64_t binary_nodes = lights > 0 ? 2 * lights - 1 : 0;
  // Both trees (a four-wide node stands for a distinct binary interior node, or the one leaf),
  // the leaf index, the lights' copy and the work lists (at most one entry per light each).
  return binary_nodes * sizeof(BinaryNode) + lights * sizeof(LightBvhNode) + slots * sizeof(LightBvhLeaf) +
         lights * (sizeof(BoundedLight) + sizeof(LightRange) + sizeof(PendingNode));
}

LightBvh build_light_bvh(std::vector<BoundedLight> lights, size_t slots) {
  LightBvh bvh;
  bvh.leaf_of_light.assign(slots, LightBvhLeaf{});
  lights.erase(std::remove_if(lights.begin(), lights.end(), [](const BoundedLight& l) { return !(l.bounds.intensity > 0); }),
               lights.end());
  if (lights.empty()) return bvh;
  std::vector<BinaryNode> binary = build_binary_tree(lights);
  bvh.nodes.reserve(std::max<size_t>(1, lights.size() - 1));
  collapse_to_four_wide(binary, bvh);
  return bvh;
}

bool sample_light_bvh(const LightBvh& bvh, vec3 p, vec3 n, float u, int& slot, float& probability) {
  if (bvh.empty()) return false;
  Descent d{0, u, 1};
  for (;;) {
    Step step = descend(bvh, p, n, d, slot);
    if (step == Step::failed) return false;
    if (step == Step::leaf) break;
  }
  probability = float(d.chosen);
  return probability > 0;
}

void sample_light_bvh_many(const LightBvh& bvh, const vec3* p, const vec3* n, const float* u, int count, int* slot,
                           float* probability) {
  constexpr int width = 4;  // descents under way at once
  for (int first = 0; first < count; first += width) {
    int group = std::min(width, count - first);
    Descent d[width];
    bool going[width] = {};
    for (int k = 0; k < group; ++k) {
      d[k] = {0, u[first + k], 1};
      going[k] = !bvh.empty();
      probability[first + k] = 0;
    }
    // Each pass takes one step of every descent still going: the steps of different descents
    // do not wait on each other, so the processor runs them side by side.
    for (bool any = true; any;) {
      any = false;
      for (int k = 0; k < group; ++k) {
        if (!going[k]) continue;
        Step step = descend(bvh, p[first + k], n[first + k], d[k], slot[first + k]);
        if (step == Step::down) {
          any = true;
          continue;
        }
        going[k] = false;
        if (step == Step::leaf) probability[first + k] = float(d[k].chosen);
      }
    }
  }
}

float light_bvh_probability(const LightBvh& bvh, vec3 p, vec3 n, int slot) {
  if (slot < 0 || size_t(slot) >= bvh.leaf_of_light.size()) return 0;
  LightBvhLeaf leaf = bvh.leaf_of_light[size_t(slot)];
  if (leaf.node < 0) return 0;
  double probability = 1;
  for (int node = leaf.node, lane = leaf.lane; node >= 0;) {
    probability *= lane_probability(lane_shares(bvh.nodes[size_t(node)], p, n), lane);
    lane = bvh.nodes[size_t(node)].parent_lane;
    node = bvh.nodes[size_t(node)].parent;
  }
  return float(probability);
}

}  // namespace radiant
