// A file's format as its name gives it: the extension, compared without regard to case.
#pragma once

#include <string>

namespace radiant {

// The path's extension in lower case, with its dot (".png"), or "".
std::string lowercase_extension(const std::string& path);

}  // namespace radiant
