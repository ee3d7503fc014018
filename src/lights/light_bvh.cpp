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
    for (int split = 0; split < split_buckets - 1; ++split) {
      LightBounds below, above;
      for (int b = 0; b <= split; ++b) below = merge(below, buckets[size_t(b)]);
      for (int b = split + 1; b < split_buckets; ++b) above = merge(above, buckets[size_t(b)]);
      float cost = group_cost(below, extent, axis) + group_cost(above, extent, axis);
      if (cost < best_cost) best_cost = cost, best_axis = axis, best_bucket = split;
    }
  }
  if (best_axis < 0) return end;
  float low = centroid_lower[best_axis], span = centroid_upper[best_axis] - low;
  return std::partition(begin, end, [&](const BoundedLight& l) { return bucket_of(l, best_axis, low, span) <= best_bucket; });
}

// Lights [begin, end) waiting to become a node below `parent` while the tree is built.
struct LightRange {
  size_t begin, end;
  int parent;
};

// The probability of stepping from interior node `node` into its first child at (p, n): by the
// children's importance; where the bounds rule both out, no light below can reach p and any
// choice is wasted (pbrt gives up there), so by intensity, which keeps every light's probability
// a distribution. One function for sampling and for the probability walk, so both agree.
double first_child_probability(const LightBvh& bvh, int node, vec3 p, vec3 n) {
  const ImportanceBounds& first = bvh.nodes[size_t(node) + 1].bounds;
  const ImportanceBounds& second = bvh.nodes[size_t(bvh.nodes[size_t(node)].second_child)].bounds;
  double a = importance(first, p, n), b = importance(second, p, n);
  if (!(a + b > 0)) a = first.intensity, b = second.intensity;
  return a / (a + b);
}

}  // namespace

uint64_t light_bvh_bytes(uint64_t lights, uint64_t slots) {
  uint64_t nodes = lights > 0 ? 2 * lights - 1 : 0;
  // The tree, the leaf index, the lights' copy and the work list (at most one range per light).
  return nodes * sizeof(LightBvhNode) + slots * sizeof(int) + lights * (sizeof(BoundedLight) + sizeof(LightRange));
}

LightBvh build_light_bvh(std::vector<BoundedLight> lights, size_t slots) {
  LightBvh bvh;
  bvh.leaf_of_light.assign(slots, -1);
  lights.erase(std::remove_if(lights.begin(), lights.end(), [](const BoundedLight& l) { return !(l.bounds.intensity > 0); }),
               lights.end());
  if (lights.empty()) return bvh;
  bvh.nodes.reserve(2 * lights.size() - 1);
  // Depth-first without recursion (a tree of many lights can be deep): a range is made a node
  // when taken from the stack; the first child is taken next, so it is always the next node.
  std::vector<LightRange> stack = {{0, lights.size(), -1}};
  while (!stack.empty()) {
    LightRange r = stack.back();
    stack.pop_back();
    int index = int(bvh.nodes.size());
    LightBvhNode& node = bvh.nodes.emplace_back();
    node.parent = r.parent;
    if (r.parent >= 0 && r.parent + 1 != index) bvh.nodes[size_t(r.parent)].second_child = index;
    if (r.end - r.begin == 1) {
      node.bounds = importance_bounds(lights[r.begin].bounds);
      node.light = lights[r.begin].slot;
      bvh.leaf_of_light[size_t(node.light)] = index;
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
  return bvh;
}

bool sample_light_bvh(const LightBvh& bvh, vec3 p, vec3 n, float u, int& slot, float& probability) {
  if (bvh.empty()) return false;
  double remaining = u, chosen = 1;
  int index = 0;
  while (!bvh.nodes[size_t(index)].is_leaf()) {
    double p_first = first_child_probability(bvh, index, p, n);
    if (remaining < p_first) {
      chosen *= p_first;
      remaining = std::min(remaining / p_first, below_one);
      index = index + 1;
    } else {
      chosen *= 1 - p_first;
      remaining = std::min((remaining - p_first) / (1 - p_first), below_one);
      index = bvh.nodes[size_t(index)].second_child;
    }
  }
  slot = bvh.nodes[size_t(index)].light;
  probability = float(chosen);
  return probability > 0;
}

float light_bvh_probability(const LightBvh& bvh, vec3 p, vec3 n, int slot) {
  if (slot < 0 || size_t(slot) >= bvh.leaf_of_light.size()) return 0;
  int index = bvh.leaf_of_light[size_t(slot)];
  if (index < 0) return 0;
  double probability = 1;
  while (index != 0) {
    int parent = bvh.nodes[size_t(index)].parent;
    double p_first = first_child_probability(bvh, parent, p, n);
    probability *= index == parent + 1 ? p_first : 1 - p_first;
    index = parent;
  }
  return float(probability);
}

}  // namespace radiant
