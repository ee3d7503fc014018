// The settings of `radiant session`: every `render` flag, as `set` and `unset` leave them.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "render_job.h"

namespace radiant::cli {

class SessionSettings {
 public:
  // `set NAME [VALUE...]`: the flag --NAME (a leading "--" may be given) with these values,
  // replacing any earlier one. Checked at once by parsing every setting as a `render` line
  // would (std::invalid_argument naming the flag): a bad value leaves the settings unchanged.
  // The flags the session itself owns are refused with what to use instead: -o (`save`), the
  // camera placement (moveto/turnto) and --max-memory (given when the session starts).
  void set(std::string name, std::vector<std::string> values);
  // `unset NAME`: back to the default. False when it was not set.
  bool unset(std::string name);

  // The session's image, whose format decides what may be set (--aov needs an EXR).
  void set_output(const std::string& output);

  // The render flags given on the session's command line, parsed by `app` as `render` parses
  // them, become settings; the options named in `owned` (long names) stay the session's.
  void set_from_command_line(const CLI::App& app, const std::vector<std::string>& owned);

  // The render these settings ask for, writing `output`; relative paths resolve against `base`.
  RenderJob job(const std::string& output, const std::filesystem::path& base) const;
  // The settings as `render` flags, in name order ("--mode path --spp 64"), as text and as words.
  std::string flags() const;
  std::vector<std::string> flag_words() const;

 private:
  std::map<std::string, std::vector<std::string>> flags_;  // name without dashes -> values
  std::string trial_output_ = "session.png";             // what `set` checks the settings against
};

}  // namespace radiant::cli
