#include "obj/obj_numbers.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

#include "message_text.h"
#include "scene/load_error.h"

namespace radiant {

namespace {

// A statement whose arguments are numbers.
struct NumberStatement {
  const char* keyword;
  size_t minimum_count;  // arguments the statement needs
  bool non_negative;     // a color or an emission
};

const std::vector<NumberStatement> obj_statements = {{"v", 3, false}, {"vn", 3, false}, {"vt", 1, false},
                                                     {"vp", 1, false}};

// Every statement tinyobjloader's LoadMtl reads with parseReal or parseInt.
const std::vector<NumberStatement> mtl_statements = {
    {"Ka", 1, true},  {"Kd", 1, true},    {"Ks", 1, true},     {"Ke", 1, true},    {"Kt", 1, true},
    {"Tf", 1, true},  {"Ns", 1, false},   {"Ni", 1, false},    {"d", 1, false},    {"Tr", 1, false},
    {"illum", 1, false}, {"Pr", 1, false}, {"Pm", 1, false},   {"Ps", 1, false},   {"Pc", 1, false},
    {"Pcr", 1, false}, {"aniso", 1, false}, {"anisor", 1, false}};

// The decimal syntax tinyobjloader parses: [+-] digits [. digits] [e [+-] digits], or with the
// digits only after the point.
bool is_decimal(const std::string& text) {
  size_t at = 0;
  auto digits = [&] {
    size_t start = at;
    while (at < text.size() && std::isdigit(static_cast<unsigned char>(text[at]))) ++at;
    return at - start;
  };
  if (at < text.size() && (text[at] == '+' || text[at] == '-')) ++at;
  size_t whole = digits(), fraction = 0;
  if (at < text.size() && text[at] == '.') ++at, fraction = digits();
  if (whole + fraction == 0) return false;
  if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
    ++at;
    if (at < text.size() && (text[at] == '+' || text[at] == '-')) ++at;
    if (digits() == 0) return false;
  }
  return at == text.size();
}

// A token and the 1-based column where it starts.
struct Word {
  std::string text;
  size_t column = 0;
};

// The words of a line up to a comment.
std::vector<Word> words_of(const std::string& line) {
  std::vector<Word> words;
  size_t at = 0;
  while (true) {
    at = line.find_first_not_of(" \t\r", at);
    if (at == std::string::npos || line[at] == '#') break;
    size_t end = line.find_first_of(" \t\r", at);
    if (end == std::string::npos) end = line.size();
    words.push_back({line.substr(at, end - at), at + 1});
    at = end;
  }
  return words;
}

void check_statement(const NumberStatement& statement, const std::vector<Word>& words, const std::string& place) {
  auto fail = [&](const Word& word, const std::string& message) {
    throw LoadError(place + ":" + std::to_string(word.column) + ": " + statement.keyword + ": " + message);
  };
  if (words.size() - 1 < statement.minimum_count)
    fail(words[0], "expected " + std::to_string(statement.minimum_count) + " numbers, found " +
                       std::to_string(words.size() - 1));
  for (size_t i = 1; i < words.size(); ++i) {
    const Word& word = words[i];
    std::string shown = "'";  // built step by step: GCC 12 warns falsely on "'" + string
    shown += escaped(word.text.substr(0, 40));
    shown += word.text.size() > 40 ? "...'" : "'";
    double value = is_decimal(word.text) ? std::strtod(word.text.c_str(), nullptr) : NAN;
    if (std::isnan(value)) fail(word, shown + " is not a number");
    if (!(std::abs(value) <= std::numeric_limits<float>::max())) fail(word, shown + " does not fit in a float");
    if (statement.non_negative && value < 0) fail(word, shown + " is negative (a color or emission must not be)");
  }
}

// The indices of an `f`, `l` or `p` statement (v, v/vt, v//vn, v/vt/vn): tinyobjloader reads them
// with atoi, which wraps past 32 bits (4294967299 reads as 3), so an index written with more
// digits than an int holds is refused here.
void check_element_indices(const std::vector<Word>& words, const std::string& place) {
  for (size_t i = 1; i < words.size(); ++i) {
    const std::string& text = words[i].text;
    for (size_t start = 0; start <= text.size();) {
      size_t end = std::min(text.find('/', start), text.size());
      std::string part = text.substr(start, end - start);
      size_t digits_from = !part.empty() && (part[0] == '-' || part[0] == '+') ? 1 : 0;
      bool integer = part.size() > digits_from &&
                     std::all_of(part.begin() + long(digits_from), part.end(), [](char c) { return c >= '0' && c <= '9'; });
      if (integer && (part.size() - digits_from > 10 || std::abs(std::stoll(part)) > std::numeric_limits<int>::max())) {
        std::string shown = "'";
        shown += part.substr(0, 40);
        shown += part.size() > 40 ? "...'" : "'";
        throw LoadError(place + ":" + std::to_string(words[i].column + start) + ": " + words[0].text + ": index " +
                        shown + " is out of range (indices are at most 2147483647 in magnitude)");
      }
      start = end + 1;
    }
  }
}

void check_numbers(std::istream& in, const std::string& file, const std::vector<NumberStatement>& statements,
                   bool with_elements) {
  std::string line;
  for (size_t number = 1; std::getline(in, line); ++number) {
    std::vector<Word> words = words_of(line);
    if (words.empty()) continue;
    if (with_elements && (words[0].text == "f" || words[0].text == "l" || words[0].text == "p"))
      check_element_indices(words, file + ":" + std::to_string(number));
    for (const NumberStatement& statement : statements)
      if (words[0].text == statement.keyword) check_statement(statement, words, file + ":" + std::to_string(number));
  }
}

}  // namespace

void check_obj_numbers(std::istream& in, const std::string& file) { check_numbers(in, file, obj_statements, true); }

void check_mtl_numbers(std::istream& in, const std::string& file) { check_numbers(in, file, mtl_statements, false); }

}  // namespace radiant
