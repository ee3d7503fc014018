#include "scene_format/scene_format_syntax.h"

#include "scene/load_error.h"

namespace radiant::scene_format {

void fail_at(const std::string& display_name, const Token& where, const std::string& message) {
  throw LoadError(display_name + ":" + std::to_string(where.line) + ":" + std::to_string(where.column) +
                  ": " + message);
}

std::string shortened(const std::string& text) {
  constexpr size_t longest = 40;  // a hostile token must not flood the one-line message
  std::string shown;
  for (size_t i = 0; i < text.size() && i < longest; ++i) {
    unsigned char c = text[i];
    shown += (c < 32 || c == 127) ? '?' : char(c);
  }
  if (text.size() > longest) shown += "...";
  return shown;
}

std::string quote(const std::string& text) {
  std::string result = "'";  // built step by step: GCC 12 warns falsely on "'" + string
  result += shortened(text);
  result += '\'';
  return result;
}

static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Reads one line without its '\n'; false at end of input. Throws past `max_line_length`.
static bool read_line(std::istream& in, std::string& line, const std::string& display_name, long line_number) {
  line.clear();
  std::streambuf* buffer = in.rdbuf();
  if (!buffer) return false;
  int c = buffer->sbumpc();
  if (c == std::char_traits<char>::eof()) return false;
  while (c != std::char_traits<char>::eof() && c != '\n') {
    if (line.size() == max_line_length)
      fail_at(display_name, {"", line_number, 1}, line_too_long_message());
    line += char(c);
    c = buffer->sbumpc();
  }
  return true;
}

// Splits a line into words; `#` starts a comment that runs to the end of the line.
static std::vector<Token> tokenize(const std::string& line, long line_number) {
  std::vector<Token> tokens;
  size_t i = 0;
  while (i < line.size() && line[i] != '#') {
    if (is_space(line[i])) {
      ++i;
      continue;
    }
    size_t start = i;
    while (i < line.size() && !is_space(line[i]) && line[i] != '#') ++i;
    tokens.push_back({line.substr(start, i - start), line_number, int(start) + 1});
  }
  return tokens;
}

// Adds one non-empty line to `text`: a block header, an attribute, or the scene line.
static void add_statement(SceneText& text, std::vector<Token> tokens, bool is_first_statement,
                          const std::string& display_name) {
  const Token& first = tokens.front();
  if (first.text[0] == '@') {
    if (first.text.size() == 1) fail_at(display_name, first, "expected a block name after '@'");
    Block block;
    block.header = first;
    block.arguments.assign(tokens.begin() + 1, tokens.end());
    text.blocks.push_back(std::move(block));
  } else if (text.blocks.empty()) {
    if (first.text == "scene" && is_first_statement) {
      text.scene_line = std::move(tokens);
      return;
    }
    if (first.text == "scene")
      fail_at(display_name, first, "the 'scene' line must be the first line of the file");
    fail_at(display_name, first,
            "attribute " + quote(first.text) + " outside a block (expected a '@block' header first)");
  } else {
    Attribute attribute;
    attribute.name = first;
    attribute.arguments.assign(tokens.begin() + 1, tokens.end());
    text.blocks.back().attributes.push_back(std::move(attribute));
  }
}

// What keeping a statement of `tokens` costs: the tokens and their text, and its block or
// attribute, each twice for the growth of the vectors holding them.
static uint64_t statement_bytes(const std::vector<Token>& tokens) {
  uint64_t bytes = sizeof(Block) + sizeof(Attribute);
  for (const Token& token : tokens) bytes += sizeof(Token) + (token.text.size() > 15 ? token.text.size() + 1 : 0);
  return 2 * bytes;
}

SceneText read_scene_text(std::istream& in, const std::string& display_name, MemoryBudget& budget) {
  SceneText text;
  std::string line;
  bool is_first_statement = true;
  for (long line_number = 1; read_line(in, line, display_name, line_number); ++line_number) {
    std::vector<Token> tokens = tokenize(line, line_number);
    if (tokens.empty()) continue;
    uint64_t bytes = statement_bytes(tokens);
    if (!budget.try_charge(bytes)) fail_at(display_name, {"", line_number, 1}, budget.refusal(bytes, "the scene text"));
    add_statement(text, std::move(tokens), is_first_statement, display_name);
    is_first_statement = false;
  }
  return text;
}

}  // namespace radiant::scene_format
