// The words of a `render` line, shared by `batch` scripts and `radiant session`: a line split
// into words, and the words parsed with the same flags as the `render` command.
#pragma once

#include <filesystem>
#include <istream>
#include <string>
#include <vector>

#include "option_parsing.h"
#include "render_job.h"

namespace radiant::cli {

// The longest command line read; a longer one is an error rather than a line held in memory whole.
constexpr size_t max_command_line = 65536;

// Reads one line of a script or session without its '\n'; false at the end. Throws
// std::invalid_argument past max_command_line characters.
bool read_command_line(std::istream& in, std::string& line);

// Splits a line into words; double quotes group words with spaces. Throws std::invalid_argument
// for an unterminated quote.
std::vector<std::string> split_words(const std::string& line);

// Binds the flags of a `render` line but -o and the animation's (the render flags, --stats,
// --aov, --crop, --noise-threshold) to `app`, storing into `flags` and `job`.
void bind_render_line_flags(CLI::App& app, RenderFlags& flags, RenderJob& job);

// `render -o OUT [flags]` as words (the first is the command name and is skipped). Relative
// paths resolve against `base`. `with_animation` also takes --time, --frame, --fps, --animation
// and --same-noise (batch scripts: each line one moment). Throws CLI::ParseError or
// std::invalid_argument, the latter also for --scene and --variant, which choose what is loaded
// and so belong where the scene loads.
RenderJob parse_render_line(std::vector<std::string> words, const std::filesystem::path& base,
                            bool with_animation = false);

}  // namespace radiant::cli
