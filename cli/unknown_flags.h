// Parsing a command's words with the checks CLI11 lacks: unknown flags (with the nearest known
// ones suggested) and flags given twice.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace radiant::cli {

// Parses a command's arguments (argv[0] is the command) with what CLI11 does not check: a flag
// given twice (`--spp 4 --spp=8`) is an error naming both, and an unknown flag is an error that
// suggests the nearest known ones (`--sampels`: did you mean --sampler or --spp?). Throws
// CLI::ParseError.
void parse_arguments(CLI::App& app, int argc, char** argv);
// The same for the words of a script line (the first word is the command).
void parse_arguments(CLI::App& app, std::vector<std::string> words);

// Each throws CLI::ValidationError naming `flag` on bad input. Numbers must be finite as floats.

}  // namespace radiant::cli
