// The command script of `radiant batch` (cli/batch_command.cpp): parsed steps and the run of
// them, so that the batch fuzzer (tests/fuzz/) runs the command's own code.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <istream>
#include <string>
#include <vector>

#include "log_level.h"
#include "render_job.h"

namespace radiant::cli {

struct BatchStep {
  int line = 0;
  std::string text;   // the line as written, without its comment
  std::string scene;  // non-empty: load this scene
  int gltf_scene = -1;          // its --scene (glTF scene index), -1: the file's default
  std::string material_variant;  // its --variant (KHR_materials_variants), "": the default materials
  RenderJob job;      // otherwise: render this
};

// Every step of the script `in`; relative paths resolve against `base`. Throws
// std::invalid_argument naming `name:line`.
std::vector<BatchStep> parse_script(std::istream& in, const std::string& name, const std::filesystem::path& base);

// `radiant batch --shard I/K`: the render steps numbered I, I+K, I+2K, ... (from 0, in script
// order) with the scene steps they render; scenes none of them renders are not loaded.
std::vector<BatchStep> shard_steps(const std::vector<BatchStep>& steps, const ShardSpec& shard);

// How a script runs: the command's flags, and (for the fuzzer) a change applied to every view.
struct BatchSettings {
  LogLevel log_level = LogLevel::info;  // -q, -qq, --quiet, --log-level: the quietest of it and a line's own
  bool allow_external_files = false;
  ProgressStyle progress = ProgressStyle::none;  // of each render (--progress), unless it is quiet
  std::optional<uint64_t> max_memory_bytes;      // --max-memory for the whole script
  std::function<RenderJob(RenderJob)> adjust_job;  // none: each view as written
};

// Checks the whole script (every scene loaded, every view resolved, nothing written) and then
// renders its views. Throws std::runtime_error "SCRIPT:LINE: why" for the first line that fails.
void run_script(const std::vector<BatchStep>& steps, const std::string& script_name, const BatchSettings& settings);

}  // namespace radiant::cli
