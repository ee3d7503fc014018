// check_shards: shards of one render covering the image x [0, spp) once merge; anything else is
// refused with one line that says what is wrong.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "film/shard_merge.h"

using namespace radiant;

namespace {

// Shard I of 4 (tiles: 2 columns x 2 rows) of a 16x8 sobol render of 32 spp.
NamedShard tile_shard(int index) {
  ShardInfo info;
  info.version = "1.0", info.scene_hash = "aa", info.settings_hash = "bb", info.isa = "avx2", info.sampler = "sobol";
  info.seed = 3, info.spp = 32, info.sample_begin = 0, info.sample_end = 32;
  info.full_width = 16, info.full_height = 8;
  info.x0 = (index % 2) * 8, info.x1 = info.x0 + 8, info.y0 = (index / 2) * 4, info.y1 = info.y0 + 4;
  info.shard_index = index, info.shard_count = 4, info.split = "tiles";
  return {"shard-" + std::to_string(index) + ".exr", info};
}

std::vector<NamedShard> all_tiles() { return {tile_shard(0), tile_shard(1), tile_shard(2), tile_shard(3)}; }

std::string refusal(const std::vector<NamedShard>& shards) {
  try {
    check_shards(shards);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace

TEST_CASE("shard merge: four tiles of one render merge into the full image of all samples") {
  ShardInfo merged = check_shards(all_tiles());
  CHECK(merged.x0 == 0);
  CHECK(merged.x1 == 16);
  CHECK(merged.y1 == 8);
  CHECK(merged.sample_end == 32);
  CHECK(merged.shard_count == 0);
}

TEST_CASE("shard merge: missing shards of --shard I/K are listed by index, ready to resubmit") {
  std::vector<NamedShard> shards = {tile_shard(0), tile_shard(2)};
  CHECK(refusal(shards) == "missing: 1,3 (of --shard I/4 --split tiles)");
}

TEST_CASE("shard merge: a gap between hand-made pieces is named by its pixels and samples") {
  std::vector<NamedShard> shards = all_tiles();
  for (NamedShard& s : shards) s.info.shard_count = 0;
  shards[3].info.sample_end = 16;  // samples 16:32 of the last tile are missing
  CHECK(refusal(shards) == "not covered by any shard: pixels 8,4,16,8 samples 16:32");
}

TEST_CASE("shard merge: overlapping shards are refused naming both files") {
  std::vector<NamedShard> shards = all_tiles();
  shards.push_back(tile_shard(2));
  shards.back().path = "again.exr";
  CHECK(refusal(shards) == "overlap: shard-2.exr and again.exr both hold pixels 0,4,8,8 samples 0:32");
}

TEST_CASE("shard merge: shards of other settings, scenes, versions or Embree ISAs are refused") {
  for (auto [field, value] : {std::pair<std::string, std::string>{"settings hash", "cc"}, {"scene hash", "dd"},
                              {"radiant version", "0.9"}, {"Embree ISA", "sse4.2"}}) {
    std::string changed = field;  // clang 14 cannot capture a structured binding in CAPTURE's lambda
    CAPTURE(changed);
    std::vector<NamedShard> shards = all_tiles();
    ShardInfo& odd = shards[2].info;
    if (field == "settings hash") odd.settings_hash = value;
    if (field == "scene hash") odd.scene_hash = value;
    if (field == "radiant version") odd.version = value;
    if (field == "Embree ISA") odd.isa = value;
    std::string message = refusal(shards);
    CHECK(message.rfind("shard-2.exr: its " + field + " '" + value + "' differs from shard-0.exr's", 0) == 0);
  }
}

TEST_CASE("shard merge: an interrupted shard is refused") {
  std::vector<NamedShard> shards = all_tiles();
  shards[1].info.partial = "interrupted by SIGTERM";
  CHECK(refusal(shards) == "shard-1.exr: the shard is incomplete (interrupted by SIGTERM); render it again");
}

TEST_CASE("shard merge: sobol sample ranges of a larger total extend a render, jittered ones cannot") {
  NamedShard first = tile_shard(0), more = tile_shard(0);
  for (NamedShard* s : {&first, &more}) s->info.x0 = 0, s->info.y0 = 0, s->info.x1 = 16, s->info.y1 = 8, s->info.shard_count = 0;
  first.info.spp = 8, first.info.sample_end = 8;
  more.info.spp = 32, more.info.sample_begin = 8, more.info.sample_end = 32;
  more.path = "more.exr";
  ShardInfo merged = check_shards({first, more});
  CHECK(merged.spp == 32);
  CHECK(merged.sample_end == 32);
  first.info.sampler = more.info.sampler = "jittered";
  CHECK(refusal({first, more}).find("more.exr: its total spp '32' differs from shard-0.exr's '8' (the strata of grid "
                                    "and jittered depend on the total spp") == 0);
}
