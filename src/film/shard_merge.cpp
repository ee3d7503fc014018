#include "film/shard_merge.h"

#include <algorithm>
#include <optional>
#include <set>
#include <stdexcept>

#include "sampling/sampler.h"
#include "scene/enum_names.h"

namespace radiant {

namespace {

// One shard as a box of pixels x samples.
struct Box {
  int64_t lo[3], hi[3];
};

Box box_of(const ShardInfo& s) { return {{s.x0, s.y0, s.sample_begin}, {s.x1, s.y1, s.sample_end}}; }

std::string describe(const Box& b) {
  return "pixels " + std::to_string(b.lo[0]) + "," + std::to_string(b.lo[1]) + "," + std::to_string(b.hi[0]) + "," +
         std::to_string(b.hi[1]) + " samples " + std::to_string(b.lo[2]) + ":" + std::to_string(b.hi[2]);
}

void require_same(const NamedShard& a, const NamedShard& b, const std::string& what, const std::string& va,
                  const std::string& vb, const std::string& why) {
  if (va != vb)
    throw std::runtime_error(b.path + ": its " + what + " '" + vb + "' differs from " + a.path + "'s '" + va + "' (" +
                             why + ")");
}

// Whether the sampler a shard names extends to a larger total spp (sampling/sampler.h).
bool extends(const std::string& sampler) {
  std::optional<SamplerKind> kind = value_named(sampler_names, sampler);
  return kind && sampler_extends(*kind);
}

void check_belong(const NamedShard& first, const NamedShard& s) {
  const ShardInfo &a = first.info, &b = s.info;
  require_same(first, s, "radiant version", a.version, b.version, "rendered by different versions");
  require_same(first, s, "Embree ISA", a.isa, b.isa, "Embree's kernels for different ISAs may round intersections differently");
  require_same(first, s, "scene hash", a.scene_hash, b.scene_hash, "rendered from different scene files");
  require_same(first, s, "alpha", a.transparent ? "transparent" : "opaque", b.transparent ? "transparent" : "opaque",
               "rendered with and without --transparent");
  require_same(first, s, "settings hash", a.settings_hash, b.settings_hash, "rendered with different settings");
  auto encoding = [](const ShardInfo& i) {
    return std::string(view_transform_name(i.display.view)) + ", exposure " + std::to_string(i.display.exposure) + ", " +
           std::to_string(i.bit_depth) + " bits" + (i.half ? ", half" : "");
  };
  require_same(first, s, "image encoding", encoding(a), encoding(b),
               "rendered with different --view, --exposure, --bit-depth or --half");
  require_same(first, s, "sampler", a.sampler, b.sampler, "rendered with different samplers");
  require_same(first, s, "seed", std::to_string(a.seed), std::to_string(b.seed), "rendered with different seeds");
  require_same(first, s, "image size", std::to_string(a.full_width) + "x" + std::to_string(a.full_height),
               std::to_string(b.full_width) + "x" + std::to_string(b.full_height), "rendered at different sizes");
  std::string aovs_a, aovs_b;
  for (const std::string& aov : a.aovs) aovs_a += aov + " ";
  for (const std::string& aov : b.aovs) aovs_b += aov + " ";
  require_same(first, s, "AOVs", aovs_a, aovs_b, "rendered with different --aov");
  if (!extends(a.sampler))
    require_same(first, s, "total spp", std::to_string(a.spp), std::to_string(b.spp),
                 "the strata of grid and jittered depend on the total spp: only sobol and random extend");
}

// The shard indices of K that none of `shards` holds, when every shard came from --shard I/K with
// one K, split and spp; "" otherwise.
std::string missing_shard_indices(const std::vector<NamedShard>& shards) {
  const ShardInfo& first = shards.front().info;
  std::set<int> present;
  for (const NamedShard& s : shards) {
    if (s.info.shard_count == 0 || s.info.shard_count != first.shard_count || s.info.split != first.split ||
        s.info.spp != first.spp)
      return "";
    present.insert(s.info.shard_index);
  }
  std::string missing;
  for (int i = 0; i < first.shard_count; ++i) {
    if (present.count(i)) continue;
    if (!missing.empty()) missing += ',';
    missing += std::to_string(i);
  }
  if (missing.empty()) return "";
  return "missing: " + missing + " (of --shard I/" + std::to_string(first.shard_count) + " --split " + first.split + ")";
}

// The first cell of the grid every box edge cuts that no box covers.
std::string first_gap(const std::vector<NamedShard>& shards, const Box& whole) {
  std::vector<int64_t> cuts[3];
  for (int axis = 0; axis < 3; ++axis) {
    std::set<int64_t> edges = {whole.lo[axis], whole.hi[axis]};
    for (const NamedShard& s : shards) edges.insert(box_of(s.info).lo[axis]), edges.insert(box_of(s.info).hi[axis]);
    cuts[axis].assign(edges.begin(), edges.end());
  }
  for (size_t k = 0; k + 1 < cuts[2].size(); ++k)
    for (size_t j = 0; j + 1 < cuts[1].size(); ++j)
      for (size_t i = 0; i + 1 < cuts[0].size(); ++i) {
        Box cell{{cuts[0][i], cuts[1][j], cuts[2][k]}, {cuts[0][i + 1], cuts[1][j + 1], cuts[2][k + 1]}};
        bool covered = std::any_of(shards.begin(), shards.end(), [&](const NamedShard& s) {
          Box b = box_of(s.info);
          return b.lo[0] <= cell.lo[0] && cell.hi[0] <= b.hi[0] && b.lo[1] <= cell.lo[1] && cell.hi[1] <= b.hi[1] &&
                 b.lo[2] <= cell.lo[2] && cell.hi[2] <= b.hi[2];
        });
        if (!covered) return "not covered by any shard: " + describe(cell);
      }
  return "";
}

}  // namespace

ShardInfo check_shards(const std::vector<NamedShard>& shards, bool whole_image) {
  if (shards.empty()) throw std::runtime_error("no shards to merge");
  ShardInfo merged = shards.front().info;
  for (const NamedShard& s : shards) {
    check_belong(shards.front(), s);
    if (!s.info.partial.empty())
      throw std::runtime_error(s.path + ": the shard is incomplete (" + s.info.partial + "); render it again");
    merged.spp = std::max(merged.spp, s.info.spp);
  }
  for (size_t i = 0; i < shards.size(); ++i)
    for (size_t j = i + 1; j < shards.size(); ++j) {
      Box a = box_of(shards[i].info), b = box_of(shards[j].info), both;
      bool overlap = true;
      for (int axis = 0; axis < 3; ++axis) {
        both.lo[axis] = std::max(a.lo[axis], b.lo[axis]), both.hi[axis] = std::min(a.hi[axis], b.hi[axis]);
        overlap = overlap && both.lo[axis] < both.hi[axis];
      }
      if (overlap)
        throw std::runtime_error("overlap: " + shards[i].path + " and " + shards[j].path + " both hold " + describe(both));
    }
  Box whole{{0, 0, 0}, {merged.full_width, merged.full_height, merged.spp}};
  if (!whole_image) {
    whole = box_of(shards.front().info);
    for (const NamedShard& s : shards)
      for (int axis = 0; axis < 3; ++axis) {
        whole.lo[axis] = std::min(whole.lo[axis], box_of(s.info).lo[axis]);
        whole.hi[axis] = std::max(whole.hi[axis], box_of(s.info).hi[axis]);
      }
  }
  // Without overlaps, the shards cover everything exactly once when their volumes add up.
  int64_t volume = 0;
  for (const NamedShard& s : shards) {
    Box b = box_of(s.info);
    volume += (b.hi[0] - b.lo[0]) * (b.hi[1] - b.lo[1]) * (b.hi[2] - b.lo[2]);
  }
  if (volume != (whole.hi[0] - whole.lo[0]) * (whole.hi[1] - whole.lo[1]) * (whole.hi[2] - whole.lo[2])) {
    std::string missing = whole_image ? missing_shard_indices(shards) : "";
    throw std::runtime_error(missing.empty() ? first_gap(shards, whole) : missing);
  }
  merged.x0 = int(whole.lo[0]), merged.y0 = int(whole.lo[1]), merged.x1 = int(whole.hi[0]), merged.y1 = int(whole.hi[1]);
  merged.sample_begin = uint32_t(whole.lo[2]), merged.sample_end = uint32_t(whole.hi[2]);
  merged.shard_index = 0, merged.shard_count = 0, merged.split.clear();
  merged.request_hash.clear();  // no one command line made it
  return merged;
}

void add_shard(Film& merged, const Film& shard) {
  bool aovs = !merged.aovs.empty() && !shard.aovs.empty();
  bool alpha = !merged.alpha.empty() && !shard.alpha.empty();
  bool halves = !merged.odd_half.empty() && !shard.odd_half.empty();
  for (int y = 0; y < shard.height; ++y)
    for (int x = 0; x < shard.width; ++x) {
      size_t from = size_t(y) * shard.width + x;
      size_t to = size_t(shard.y - merged.y + y) * merged.width + size_t(shard.x - merged.x + x);
      add_pixel(merged.pixels[to], shard.pixels[from]);
      if (aovs) add_aovs(merged.aovs[to], shard.aovs[from]);
      if (alpha) merged.alpha[to].add(shard.alpha[from]);
      if (halves) add_half(merged.odd_half[to], shard.odd_half[from]);
    }
}

}  // namespace radiant
