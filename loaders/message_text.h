// Text from files and libraries made fit for radiant's one-line error messages.
#pragma once

#include <cstddef>
#include <string>

namespace radiant {

// The most bytes of a file's text (or of a library's message, which may echo it: a whole data
// URI) that one message quotes; longer text is cut, saying its length.
constexpr size_t max_message_excerpt = 300;

// Joins a library's multi-line message into one line ("; " between non-empty lines), at most
// max_message_excerpt bytes of it.
std::string one_line(const std::string& text);

// Text from a file (a URI, a name) made safe to show inside a one-line message: control bytes,
// NUL included, are written as \n, \r, \t or \xNN instead of cutting or breaking the line, and
// at most max_message_excerpt bytes of it are shown.
std::string escaped(const std::string& text);

}  // namespace radiant
