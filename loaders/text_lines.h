// The line limit of radiant's text formats (.scene, OBJ, MTL): one hostile line must not take
// all memory before anything is charged to the budget.
#pragma once

#include <cstddef>
#include <istream>
#include <string>

namespace radiant {

// Longest line accepted, in bytes without its '\n'.
constexpr size_t max_line_length = 1 << 20;

// The message for a line past max_line_length.
std::string line_too_long_message();

// Reads `in` from where it stands to its end through a small buffer, and throws LoadError
// "file:LINE: line is longer than 1048576 characters" at the first line past max_line_length.
void check_line_lengths(std::istream& in, const std::string& file);

}  // namespace radiant
