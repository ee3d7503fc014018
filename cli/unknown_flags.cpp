#include "unknown_flags.h"

#include <algorithm>
#include <cctype>
#include <utility>

#include "scene/enum_names.h"

namespace radiant::cli {

namespace {

// Edit distance with transpositions (optimal string alignment): "sampels" is 1 from "samples".
size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// Names other renderers use for our flags: pbrt's and Cycles' words.
const std::vector<std::pair<std::string, std::string>> flag_synonyms = {
    {"samples", "spp"},       {"sample", "spp"},         {"spp-max", "spp"},      {"out", "output"},
    {"outfile", "output"},    {"integrator", "mode"},    {"maxdepth", "max-depth"}, {"depth", "max-depth"},
    {"resolution", "width"},  {"xres", "width"},         {"yres", "height"},      {"nthreads", "threads"},
    {"environment", "env"},   {"hdri", "env"},           {"world", "env"}};

std::string suggestions(const CLI::App& app, const std::string& unknown) {
  std::vector<std::string> found;
  auto add = [&](const std::string& name) {
    if (std::find(found.begin(), found.end(), name) == found.end()) found.push_back(name);
  };
  for (const CLI::Option* option : app.get_options()) {
    for (const std::string& name : option->get_lnames()) {
      size_t distance = edit_distance(unknown, name);
      if (distance <= std::max<size_t>(1, name.size() / 3) || (unknown.size() >= 3 && name.rfind(unknown, 0) == 0))
        add("--" + name);
    }
  }
  for (const auto& [synonym, name] : flag_synonyms)
    if (edit_distance(unknown, synonym) <= std::max<size_t>(1, synonym.size() / 3) && app.get_option_no_throw("--" + name))
      add("--" + name);
  return choices_text(found);
}

// The flags among `words` (not their values): unknown ones and repeated ones are errors.
void check_flag_words(const CLI::App& app, const std::vector<std::string>& words) {
  std::vector<std::pair<const CLI::Option*, std::string>> seen;
  for (const std::string& word : words) {
    if (word == "--") break;  // what follows is positional
    bool flag = word.size() >= 2 && word[0] == '-' && (word[1] == '-' || (word.size() == 2 && std::isalpha(static_cast<unsigned char>(word[1]))));
    if (!flag) continue;  // a value ("-1,2,3", "-5", "-")
    std::string name = word.substr(0, word.find('='));
    const CLI::Option* option = app.get_option_no_throw(name);
    if (!option) {
      if (name == "-h" || name == "--help" || name == "--version") continue;
      std::string near = suggestions(app, name.substr(name[1] == '-' ? 2 : 1));
      throw CLI::ValidationError(name, "unknown flag" + (near.empty() ? std::string(" (--help lists them)") : "; did you mean " + near + "?"));
    }
    for (const auto& [earlier, as] : seen)
      if (earlier == option) throw CLI::ValidationError(name, "given twice (" + as + " and " + word + ")");
    seen.emplace_back(option, word);
  }
}

}  // namespace

void parse_arguments(CLI::App& app, int argc, char** argv) {
  check_flag_words(app, std::vector<std::string>(argv + 1, argv + argc));
  app.parse(argc, argv);
}

void parse_arguments(CLI::App& app, std::vector<std::string> words) {
  check_flag_words(app, std::vector<std::string>(words.begin() + 1, words.end()));
  std::reverse(words.begin(), words.end());
  words.pop_back();  // the command name
  app.parse(words);
}

}  // namespace radiant::cli
