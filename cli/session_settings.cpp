#include "session_settings.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <stdexcept>

#include "render_line.h"

namespace radiant::cli {

namespace {

// The flags a session owns: what to use instead of setting them.
std::string owned_by_session(const std::string& name) {
  if (name == "o" || name == "output") return "the session writes the image named on its command line; use 'save FILE'";
  if (name == "look-from" || name == "look-at" || name == "up") return "use moveto/move and turnto/turn";
  if (name == "max-memory") return "give --max-memory when the session starts";
  if (name == "time-limit") return "not a session setting";
  if (name == "scene" || name == "variant") return "chooses what is loaded, not a session setting";
  return "";
}

std::string flag_name(std::string name) {
  if (name.rfind("--", 0) == 0) name.erase(0, 2);
  else if (name == "-q" || name == "-qq") name = "log-level";
  if (name.empty()) throw std::invalid_argument("a setting needs a name");
  if (std::string why = owned_by_session(name); !why.empty()) throw std::invalid_argument("--" + name + ": " + why);
  return name;
}

}  // namespace

void SessionSettings::set(std::string name, std::vector<std::string> values) {
  if (name == "-q" || name == "-qq") values = {name == "-q" ? "warning" : "error"};
  name = flag_name(name);
  if (values.empty()) {
    // Alone on a command line, a flag that needs a value says so itself (among the other
    // settings, it would take the next flag as its value).
    try {
      parse_render_line({"render", "-o", trial_output_, "--" + name}, ".");
    } catch (const CLI::ParseError& e) {
      throw std::invalid_argument("set " + name + " needs a value: " + e.what());
    }
  }
  SessionSettings trial = *this;
  trial.flags_[name] = std::move(values);
  try {
    trial.job(trial_output_, ".");
  } catch (const CLI::ParseError& e) {
    throw std::invalid_argument(e.what());
  }
  *this = std::move(trial);
}

void SessionSettings::set_output(const std::string& output) {
  trial_output_ = "session" + std::filesystem::path(output).extension().string();
}

bool SessionSettings::unset(std::string name) { return flags_.erase(flag_name(name)) > 0; }

void SessionSettings::set_from_command_line(const CLI::App& app, const std::vector<std::string>& owned) {
  for (const CLI::Option* option : app.get_options()) {
    if (option->count() == 0 || option->get_positional()) continue;
    if (option->get_lnames().empty()) {  // -q, -qq
      set(option->count() > 1 ? "-qq" : "-q", {});
      continue;
    }
    const std::string& name = option->get_lnames().front();
    if (name == "help" || std::find(owned.begin(), owned.end(), name) != owned.end()) continue;
    // A flag's results are CLI11's own words for "given"; the flag alone says it.
    set("--" + name, option->get_expected_min() == 0 ? std::vector<std::string>{} : option->results());
  }
}

RenderJob SessionSettings::job(const std::string& output, const std::filesystem::path& base) const {
  std::vector<std::string> words = {"render", "-o", output};
  for (const std::string& word : flag_words()) words.push_back(word);
  return parse_render_line(words, base);
}

std::string SessionSettings::flags() const {
  std::string text;
  for (const std::string& word : flag_words()) text += (text.empty() ? "" : " ") + word;
  return text;
}

std::vector<std::string> SessionSettings::flag_words() const {
  std::vector<std::string> words;
  for (const auto& [name, values] : flags_) {
    words.push_back("--" + name);
    words.insert(words.end(), values.begin(), values.end());
  }
  return words;
}

}  // namespace radiant::cli
