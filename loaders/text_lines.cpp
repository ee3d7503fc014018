#include "text_lines.h"

#include "scene/load_error.h"

namespace radiant {

std::string line_too_long_message() {
  return "line is longer than " + std::to_string(max_line_length) + " characters";
}

void check_line_lengths(std::istream& in, const std::string& file) {
  char buffer[1 << 16];
  size_t line = 1, length = 0;
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    for (std::streamsize i = 0; i < in.gcount(); ++i) {
      if (buffer[i] == '\n') {
        ++line, length = 0;
      } else if (++length > max_line_length) {
        throw LoadError(file + ":" + std::to_string(line) + ": " + line_too_long_message());
      }
    }
  }
}

}  // namespace radiant
