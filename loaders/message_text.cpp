#include "message_text.h"

#include <cctype>
#include <cstdio>
#include <sstream>

namespace radiant {

namespace {

// `text` cut to at most `longest` bytes, at a character boundary, saying how long it was.
std::string shortened(const std::string& text, size_t longest) {
  if (text.size() <= longest) return text;
  size_t cut = longest;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // inside a UTF-8 character
  return text.substr(0, cut) + "... (" + std::to_string(text.size()) + " bytes)";
}

}  // namespace

std::string one_line(const std::string& text) {
  std::istringstream lines(text);
  std::string line, out;
  while (std::getline(lines, line) && out.size() <= max_message_excerpt) {
    while (!line.empty() && std::isspace((unsigned char)line.back())) line.pop_back();
    if (!line.empty()) out += (out.empty() ? "" : "; ") + line;
  }
  return shortened(out, max_message_excerpt);
}

std::string escaped(const std::string& whole) {
  std::string out, text = shortened(whole, max_message_excerpt);
  for (char c : text) {
    unsigned char byte = static_cast<unsigned char>(c);
    if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else if (c == '\t') out += "\\t";
    else if (byte < 0x20 || byte == 0x7F) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", byte);
      out += hex;
    } else out += c;
  }
  return out;
}

}  // namespace radiant
