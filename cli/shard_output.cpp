#include "shard_output.h"

#include <algorithm>
#include <filesystem>
#include <iostream>

#include "accel/embree_isa.h"
#include "option_parsing.h"
#include "render/settings_hash.h"
#include "render/shard_plan.h"
#include "shard_request.h"

namespace radiant::cli {

bool writes_shard(const RenderOptions& options) { return options.shard || options.sample_range; }

ShardInfo make_shard_info(const PreparedScene& prepared, const ResolvedSettings& s, const RenderOptions& options,
                          const std::string& request_hash) {
  std::vector<std::string> files = prepared.scene->input_files;
  // An environment map is read when rendering, not loading: it belongs to the scene all the same.
  const std::string& map = s.environment.map_path;
  if (!map.empty() && std::find(files.begin(), files.end(), map) == files.end()) files.push_back(map);
  ShardInfo info;
  info.version = RADIANT_VERSION;
  info.scene_hash = files_hash(files);
  info.request_hash = request_hash;
  // After the scene file itself (which the command line names), where each file was read: a
  // later run hashes them there before loading anything.
  for (size_t i = 1; i < files.size(); ++i) info.inputs.push_back(resolved_path(files[i]));
  info.settings_hash = settings_hash(s, options);
  info.isa = embree_kernels_name();
  info.sampler = sampler_name(s.sampler);
  info.seed = options.seed;
  info.spp = uint32_t(s.spp);
  info.sample_begin = s.samples.begin, info.sample_end = s.samples.end;
  info.x0 = s.window.x0, info.y0 = s.window.y0, info.x1 = s.window.x1, info.y1 = s.window.y1;
  info.full_width = s.width, info.full_height = s.height;
  info.aovs = options.aovs;
  info.transparent = s.transparent;
  info.display = {options.exposure, s.view};
  info.bit_depth = options.bit_depth;
  info.half = options.half_float;
  if (options.shard) {
    info.shard_index = options.shard->index, info.shard_count = options.shard->count;
    info.split = split_name(options.shard->split);
  }
  return info;
}

bool shard_already_rendered(const std::string& path, const ShardInfo& expected, MemoryBudget* budget) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return false;
  try {
    ShardInfo found = read_shard_info(path, budget);
    found.request_hash = expected.request_hash;
    if (!(found == expected)) return false;
    read_shard_film(path, found, budget);  // its accumulators intact: a damaged shard is rendered again
    return true;
  } catch (const std::runtime_error&) {
    return false;  // not a shard of ours (or damaged): rendering it again replaces it
  }
}

void report_shard_skipped(const std::string& output, bool quiet) {
  if (!quiet) std::cerr << "radiant: " << output << " already holds this shard, complete; skipped\n";
}

}  // namespace radiant::cli
