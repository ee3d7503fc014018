// A command line as one line of text a shell runs again: what an image records as the command
// that made it (image/render_metadata.h).
#pragma once

#include <string>
#include <vector>

namespace radiant::cli {

// `word` as one POSIX shell word: as it is when it holds only characters no shell treats
// specially, else in single quotes ('it'\''s').
std::string shell_word(const std::string& word);

// "radiant COMMAND ARG..." from a command's argv (argv[0] is the command name), each word as a
// shell word.
std::string command_line_text(int argc, char** argv);
// The same for words (the first is the command name).
std::string command_line_text(const std::vector<std::string>& words);

}  // namespace radiant::cli
