// How much a command prints on stderr besides errors: `-q` keeps warnings, `-qq` and `--quiet`
// keep errors only, `--log-level` names the level.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace radiant::cli {

enum class LogLevel { error, warning, info };

// The flags bound to an app; `level()` after parsing. Throws CLI::ValidationError for a bad
// --log-level.
struct LogLevelFlags {
  int q_count = 0;        // -q, -qq
  bool quiet = false;     // --quiet: errors only, as scripts expect
  std::string log_level;  // error, warning or info
  void bind(CLI::App& app);
  // The quietest level asked for; info when nothing was given.
  LogLevel level() const;
};

// Whether a line of `kind` shows at `level`.
inline bool shows(LogLevel level, LogLevel kind) { return int(kind) <= int(level); }

}  // namespace radiant::cli
