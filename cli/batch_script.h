// The command script of `radiant batch` (cli/batch_command.cpp) as parsed steps, so the batch
// fuzzer (tests/fuzz/) runs the same parser as the command.
#pragma once

#include <filesystem>
#include <istream>
#include <string>
#include <vector>

#include "render_job.h"

namespace radiant::cli {

struct BatchStep {
  int line = 0;
  std::string scene;  // non-empty: load this scene
  RenderJob job;      // otherwise: render this
};

// Every step of the script `in`; relative paths resolve against `base`. Throws
// std::invalid_argument naming `name:line`.
std::vector<BatchStep> parse_script(std::istream& in, const std::string& name, const std::filesystem::path& base);

}  // namespace radiant::cli
