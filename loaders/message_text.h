// Text from files and libraries made fit for radiant's one-line error messages.
#pragma once

#include <string>

namespace radiant {

// Joins a library's multi-line message into one line ("; " between non-empty lines).
std::string one_line(const std::string& text);

// Text from a file (a URI, a name) made safe to show inside a one-line message: control bytes,
// NUL included, are written as \n, \r, \t or \xNN instead of cutting or breaking the line.
std::string escaped(const std::string& text);

}  // namespace radiant
