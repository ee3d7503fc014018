// The syntax layer of the .scene format: lines to tokens to blocks, each word with its position.
// It records what the file says; giving it meaning is the job of the block builders.
#pragma once

#include <cstddef>
#include <istream>
#include <string>
#include <vector>

#include "memory/memory_budget.h"
#include "text_lines.h"

namespace radiant::scene_format {

// A word of the file and where it starts (1-based line and byte column).
struct Token {
  std::string text;
  long line = 0;
  int column = 0;
};

// One attribute line under a block header: `name arguments...`.
struct Attribute {
  Token name;
  std::vector<Token> arguments;
};

// A `@kind arguments...` header and the attribute lines under it.
struct Block {
  Token header;  // the `@kind` word, '@' included
  std::vector<Token> arguments;
  std::vector<Attribute> attributes;
  std::string kind() const { return header.text.substr(1); }
};

// The whole file as written.
struct SceneText {
  std::vector<Token> scene_line;  // the optional first line `scene NAME...`; empty when absent
  std::vector<Block> blocks;
};

using radiant::max_line_length;  // text_lines.h: the limit every text format shares

// Reads `in` to the end, charging every statement's tokens to `budget` before keeping them (a
// two-byte word takes a 48-byte Token). Throws LoadError on over-long lines, on text the budget
// refuses, and on attribute lines before the first block.
SceneText read_scene_text(std::istream& in, const std::string& display_name, MemoryBudget& budget);

// Throws LoadError `display_name:line:col: message`.
[[noreturn]] void fail_at(const std::string& display_name, const Token& where, const std::string& message);

// `text` for messages: at most 40 characters, control bytes replaced.
std::string shortened(const std::string& text);
// `text` shortened and in single quotes.
std::string quote(const std::string& text);

}  // namespace radiant::scene_format
