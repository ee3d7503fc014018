#include "command_line.h"

namespace radiant::cli {

std::string shell_word(const std::string& word) {
  bool plain = !word.empty() && word.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                                       "0123456789_-+=/.,:@%") == std::string::npos;
  if (plain) return word;
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string command_line_text(const std::vector<std::string>& words) {
  std::string text = "radiant";
  for (const std::string& word : words) text += " " + shell_word(word);
  return text;
}

std::string command_line_text(int argc, char** argv) { return command_line_text(std::vector<std::string>(argv, argv + argc)); }

}  // namespace radiant::cli
