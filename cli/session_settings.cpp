#include "session_settings.h"

#include <CLI/CLI.hpp>

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
  else if (name == "-q") name = "quiet";
  if (name.empty()) throw std::invalid_argument("a setting needs a name");
  if (std::string why = owned_by_session(name); !why.empty()) throw std::invalid_argument("--" + name + ": " + why);
  return name;
}

}  // namespace

void SessionSettings::set(std::string name, std::vector<std::string> values) {
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

void SessionSettings::set_from_arguments(const std::vector<std::string>& arguments) {
  std::map<std::string, std::string> given;  // name -> the word that gave it
  for (size_t i = 0; i < arguments.size();) {
    std::string word = arguments[i++], as_given = word;
    if (word.rfind("-", 0) != 0) throw std::invalid_argument("unexpected argument '" + word + "'");
    std::vector<std::string> values;
    if (size_t equals = word.find('='); equals != std::string::npos) {
      values.push_back(word.substr(equals + 1));
      word.resize(equals);
    } else {
      // Values follow until the next flag ("-1,2,3" is a value, "--seed" a flag).
      while (i < arguments.size() && arguments[i].rfind("--", 0) != 0 && arguments[i] != "-q") values.push_back(arguments[i++]);
    }
    if (auto [at, fresh] = given.emplace(flag_name(word), as_given); !fresh)
      throw std::invalid_argument(word + ": given twice (" + at->second + " and " + as_given + ")");
    set(word, values);
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
