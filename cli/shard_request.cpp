#include "shard_request.h"

#include <algorithm>
#include <filesystem>
#include <system_error>
#include <vector>

#include "accel/embree_isa.h"
#include "film/shard_file.h"
#include "render/settings_hash.h"

namespace radiant::cli {

namespace fs = std::filesystem;

namespace {

// Flags that change where or how loudly a shard is written, or whether it can be, never its
// bytes. (--exposure, --view, --bit-depth and --half do: the shard records them for merge.)
const char* const flags_outside_the_shard[] = {"output", "threads", "max-memory", "quiet", "log-level", "stats", "skip-existing",
                                                "format"};

}  // namespace

std::string resolved_path(const std::string& path) {
  std::error_code error;
  fs::path resolved = fs::weakly_canonical(fs::absolute(path, error), error);
  return error ? path : resolved.string();
}

std::string shard_request_hash(const CLI::App& app, const std::string& scene_path) {
  std::vector<std::string> words;
  for (const CLI::Option* option : app.get_options()) {
    if (option->count() == 0 || option->get_lnames().empty()) continue;  // not given, or the positional SCENE
    const std::string& name = option->get_lnames().front();
    if (std::find(std::begin(flags_outside_the_shard), std::end(flags_outside_the_shard), name) !=
        std::end(flags_outside_the_shard))
      continue;
    std::string word = "--" + name;
    for (const std::string& value : option->results()) word += '\n' + (name == "env" ? resolved_path(value) : value);
    words.push_back(word);
  }
  std::sort(words.begin(), words.end());  // the order flags were given in does not matter
  std::string text = resolved_path(scene_path);
  for (const std::string& word : words) text += '\0' + word;
  return text_hash(text);
}

bool shard_unchanged_before_load(const std::string& output, const std::string& scene_path, const std::string& request_hash,
                                 MemoryBudget* budget) {
  std::error_code error;
  if (!fs::is_regular_file(output, error)) return false;
  try {
    ShardInfo found = read_shard_info(output, budget);
    if (found.request_hash != request_hash || !found.partial.empty() || found.version != RADIANT_VERSION ||
        found.isa != embree_kernels_name())
      return false;
    std::vector<std::string> files = {scene_path};
    files.insert(files.end(), found.inputs.begin(), found.inputs.end());
    if (files_hash(files) != found.scene_hash) return false;
    read_shard_film(output, found, budget);  // its accumulators intact: a damaged shard is rendered again
    return true;
  } catch (const std::runtime_error&) {
    return false;  // not a shard, damaged, or a file it read is gone: the full check decides
  }
}

}  // namespace radiant::cli
