#include "lights/light_bvh.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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

// The binary tree the build makes first (pbrt-v4's), before it is collapsed to eight-wide nodes.
struct BinaryNode {
  ImportanceBounds bounds;
  int second_child = -1;  // interior nodes: the first child is the next node
  int light = -1;         // leaves: the light's slot
  bool is_leaf() const { return light >= 0; }
};

// A binary interior node waiting to become an eight-wide node, in lane `lane` of `parent`.
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

// The lanes of the eight-wide node that stands for binary interior node `b`: its two children,
// then, while a lane is free, the interior lane with the widest bounding sphere replaced by its
// own two children. A lane is rated by its own bounds, so opening the loosest group first sharpens
// the choice most (on assets/many-lights.scene, 2% less error at equal samples than opening the
// group with the most lights, with the same depth: a descent takes about log8 of the lights'
// number of steps). A node short of eight lanes holds only leaves.
int wide_node_lanes(const std::vector<BinaryNode>& binary, int b, int (&lanes)[light_node_width]) {
  int count = 0;
  lanes[count++] = b + 1;
  lanes[count++] = binary[size_t(b)].second_child;
  while (count < light_node_width) {
    int widest = -1;
    for (int lane = 0; lane < count; ++lane) {
      const BinaryNode& node = binary[size_t(lanes[lane])];
      if (!node.is_leaf() && (widest < 0 || node.bounds.radius2 > binary[size_t(lanes[widest])].bounds.radius2))
        widest = lane;
    }
    if (widest < 0) break;
    int opened = lanes[widest];
    lanes[widest] = opened + 1;
    lanes[count++] = binary[size_t(opened)].second_child;
  }
  return count;
}

void collapse_to_wide_nodes(const std::vector<BinaryNode>& binary, LightBvh& bvh) {
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
    int lanes[light_node_width];
    int count = wide_node_lanes(binary, pending.binary, lanes);
    for (int lane = 0; lane < count; ++lane) put(index, lane, lanes[lane]);
  }
}

// How a node shares the choice among its lanes at (p, n): by the children's importance; where
// the bounds rule all out, no light below can reach p and any choice is wasted (pbrt gives up
// there), so by intensity, which keeps every light's probability a distribution. Lane k's share
// of [0, total) is [start[k], start[k + 1]) (the last lane's ends at total); its probability
// rated[k] / total. One function for sampling and for the probability walk, so both agree.
// Inline: called, it kept p and n in memory across the call and returned the shares through the
// stack, on every step of the descent (2.7% of a many-lights render).
struct LaneShares {
  float rated[light_node_width];
  float start[light_node_width];  // 0, rated[0], rated[0] + rated[1], ... (summed as sum_shares says)
  float total;                    // 0 only for a node that holds no light
};

// The running sums and the total. Each half of four lanes is summed as (x0 + x1) + (x2 + x3),
// its running sums as 0, x0, x0 + x1, (x0 + x1) + x2; the upper half's start past the lower
// half's total. Starts never decrease (adding a rating that is not negative never lowers a sum,
// rounding included), which the lane choice relies on. With SSE2 the halves are summed side by
// side in registers, the same additions in the same order as the scalar code's.
[[gnu::always_inline]] inline void sum_shares(LaneShares& shares) {
  const float* r = shares.rated;
#if defined(__SSE2__)
  auto shift_up = [](__m128 v) { return _mm_castsi128_ps(_mm_slli_si128(_mm_castps_si128(v), 4)); };
  auto running = [&](__m128 x, __m128& starts) {  // the half's starts; returns its total in lane 3
    __m128 pairs = _mm_add_ps(x, shift_up(x));  // x0, x1 + x0, x2 + x1, x3 + x2
    __m128 ends = _mm_shuffle_ps(x, pairs, _MM_SHUFFLE(3, 1, 2, 0));
    ends = _mm_shuffle_ps(ends, ends, _MM_SHUFFLE(3, 1, 2, 0));  // x0, x1 + x0, x2, x3 + x2
    __m128 below = _mm_shuffle_ps(_mm_setzero_ps(), pairs, _MM_SHUFFLE(1, 1, 0, 0));  // 0, 0, x0 + x1, x0 + x1
    __m128 inclusive = _mm_add_ps(ends, below);
    starts = shift_up(inclusive);
    return _mm_cvtss_f32(_mm_shuffle_ps(inclusive, inclusive, _MM_SHUFFLE(3, 3, 3, 3)));
  };
  __m128 low_starts, high_starts;
  float low = running(_mm_loadu_ps(r), low_starts);
  float high = running(_mm_loadu_ps(r + 4), high_starts);
  _mm_storeu_ps(shares.start, low_starts);
  _mm_storeu_ps(shares.start + 4, _mm_add_ps(_mm_set1_ps(low), high_starts));
  shares.total = low + high;
#else
  float low_pair = r[0] + r[1], high_pair = r[4] + r[5];
  float low = low_pair + (r[3] + r[2]), high = high_pair + (r[7] + r[6]);
  shares.start[0] = 0;
  shares.start[1] = r[0], shares.start[2] = low_pair, shares.start[3] = r[2] + low_pair;
  shares.start[4] = low + 0, shares.start[5] = low + r[4], shares.start[6] = low + high_pair;
  shares.start[7] = low + (r[6] + high_pair);
  shares.total = low + high;
#endif
}

[[gnu::always_inline]] inline LaneShares lane_shares(const LightBvhNode& node, vec3 p, vec3 n) {
  LaneShares shares;
  importance8(node.bounds, p, n, shares.rated);
  sum_shares(shares);
  if (!(shares.total > 0)) {
    for (int lane = 0; lane < light_node_width; ++lane) shares.rated[lane] = node.bounds.intensity[lane];
    sum_shares(shares);
  }
  return shares;
}

// Bit k set where lane k is rated and its share starts at or below `t`. With SSE2 (every x86-64
// CPU has it, and AVX2 code runs it too) two compares of four lanes; comparisons are exact, so
// this is the scalar loop's answer on every instruction set.
[[gnu::always_inline]] inline unsigned lane_candidates(const LaneShares& shares, float t) {
#if defined(__SSE2__)
  __m128 target = _mm_set1_ps(t), zero = _mm_setzero_ps();
  __m128 low = _mm_and_ps(_mm_cmple_ps(_mm_loadu_ps(shares.start), target), _mm_cmpgt_ps(_mm_loadu_ps(shares.rated), zero));
  __m128 high =
      _mm_and_ps(_mm_cmple_ps(_mm_loadu_ps(shares.start + 4), target), _mm_cmpgt_ps(_mm_loadu_ps(shares.rated + 4), zero));
  return unsigned(_mm_movemask_ps(low)) | unsigned(_mm_movemask_ps(high)) << 4;
#else
  unsigned candidates = 0;
  for (int k = 0; k < light_node_width; ++k)
    candidates |= unsigned(int(shares.start[k] <= t) & int(shares.rated[k] > 0)) << k;
  return candidates;
#endif
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
  // it. The shares' starts never decrease, so it is the last rated lane that starts at or below
  // the target: a lane rated 0 is passed over, and the target rounded past the total (or into
  // empty lanes at the end) goes to the last rated lane: the highest bit of lane_candidates.
  // Only the next node waits on this: the divisions that rescale `remaining` and form the
  // probability run beside the next node's rating.
  double target = d.remaining * shares.total;
  float t = float(target);
  int lane = 31 - __builtin_clz(lane_candidates(shares, t) | 1u);  // lane 0 where none qualifies
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

// A node short of eight lanes holds only leaves, at least two (one in a tree of one light), so
// there are at most lights / 2 of those; interior lanes sit only in full nodes, and counting
// lanes (lights + nodes - 1 of them) leaves room for at most (lights - 1) / 7 full ones.
uint64_t light_bvh_nodes_at_most(uint64_t lights) { return lights / 2 + lights / 7 + 1; }

uint64_t light_bvh_bytes(uint64_t lights, uint64_t slots) {
  uint64_t binary_nodes = lights > 0 ? 2 * lights - 1 : 0;
  // Both trees, the leaf index, the lights' copy and the work lists (at most one entry per light
  // each).
  return binary_nodes * sizeof(BinaryNode) + light_bvh_nodes_at_most(lights) * sizeof(LightBvhNode) +
         slots * sizeof(LightBvhLeaf) + lights * (sizeof(BoundedLight) + sizeof(LightRange) + sizeof(PendingNode));
}

LightBvh build_light_bvh(std::vector<BoundedLight> lights, size_t slots) {
  LightBvh bvh;
  bvh.leaf_of_light.assign(slots, LightBvhLeaf{});
  lights.erase(std::remove_if(lights.begin(), lights.end(), [](const BoundedLight& l) { return !(l.bounds.intensity > 0); }),
               lights.end());
  if (lights.empty()) return bvh;
  std::vector<BinaryNode> binary = build_binary_tree(lights);
  bvh.nodes.reserve(size_t(light_bvh_nodes_at_most(lights.size())));
  collapse_to_wide_nodes(binary, bvh);
  return bvh;
}

namespace {

// The three ways into the tree, each compiled twice below: for the x86-64 baseline and for AVX2,
// where importance8's loop is one eight-wide pass. Inline into those wrappers, which is where GCC
// vectorises it.
[[gnu::always_inline]] inline bool choose_one(const LightBvh& bvh, vec3 p, vec3 n, float u, int& slot, float& probability) {
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

[[gnu::always_inline]] inline void choose_many(const LightBvh& bvh, const vec3* p, const vec3* n, const float* u,
                                               int count, int* slot, float* probability) {
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

[[gnu::always_inline]] inline float probability_of(const LightBvh& bvh, vec3 p, vec3 n, int slot) {
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

bool choose_one_baseline(const LightBvh& bvh, vec3 p, vec3 n, float u, int& slot, float& probability) {
  return choose_one(bvh, p, n, u, slot, probability);
}
[[gnu::target("avx2")]] bool choose_one_avx2(const LightBvh& bvh, vec3 p, vec3 n, float u, int& slot, float& probability) {
  return choose_one(bvh, p, n, u, slot, probability);
}
void choose_many_baseline(const LightBvh& bvh, const vec3* p, const vec3* n, const float* u, int count, int* slot,
                          float* probability) {
  choose_many(bvh, p, n, u, count, slot, probability);
}
[[gnu::target("avx2")]] void choose_many_avx2(const LightBvh& bvh, const vec3* p, const vec3* n, const float* u,
                                             int count, int* slot, float* probability) {
  choose_many(bvh, p, n, u, count, slot, probability);
}
float probability_of_baseline(const LightBvh& bvh, vec3 p, vec3 n, int slot) { return probability_of(bvh, p, n, slot); }
[[gnu::target("avx2")]] float probability_of_avx2(const LightBvh& bvh, vec3 p, vec3 n, int slot) {
  return probability_of(bvh, p, n, slot);
}

}  // namespace

bool sample_light_bvh(const LightBvh& bvh, vec3 p, vec3 n, float u, int& slot, float& probability, LaneIsa isa) {
  return resolve_lane_isa(isa) == LaneIsa::avx2 ? choose_one_avx2(bvh, p, n, u, slot, probability)
                                                : choose_one_baseline(bvh, p, n, u, slot, probability);
}

void sample_light_bvh_many(const LightBvh& bvh, const vec3* p, const vec3* n, const float* u, int count, int* slot,
                           float* probability, LaneIsa isa) {
  resolve_lane_isa(isa) == LaneIsa::avx2 ? choose_many_avx2(bvh, p, n, u, count, slot, probability)
                                         : choose_many_baseline(bvh, p, n, u, count, slot, probability);
}

float light_bvh_probability(const LightBvh& bvh, vec3 p, vec3 n, int slot, LaneIsa isa) {
  return resolve_lane_isa(isa) == LaneIsa::avx2 ? probability_of_avx2(bvh, p, n, slot)
                                                : probability_of_baseline(bvh, p, n, slot);
}

}  // namespace radiant
