#include "log_level.h"

#include <algorithm>

namespace radiant::cli {

void LogLevelFlags::bind(CLI::App& app) {
  app.add_flag("-q", q_count, "Quieter: -q hides informational lines and keeps warnings, -qq keeps errors only");
  app.add_flag("--quiet", quiet, "Print nothing but errors (the same as -qq)");
  app.add_option("--log-level", log_level, "What stderr shows besides errors: info (default), warning or error");
}

LogLevel LogLevelFlags::level() const {
  LogLevel level = LogLevel::info;
  if (log_level == "warning") level = LogLevel::warning;
  else if (log_level == "error") level = LogLevel::error;
  else if (!log_level.empty() && log_level != "info")
    throw CLI::ValidationError("--log-level", "expected info, warning or error, not '" + log_level + "'");
  if (q_count == 1) level = std::min(level, LogLevel::warning);
  if (q_count >= 2 || quiet) level = LogLevel::error;
  return level;
}

}  // namespace radiant::cli
