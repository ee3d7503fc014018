// The check every file radiant reads for a scene passes before it is opened: a FIFO or a device
// would block or never end, and a file's size must be known before anything is allocated for it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace radiant {

// "" when `path` (symlinks followed) is a regular file, with its size in `size`; otherwise what
// is wrong: "no such file", "is a directory", "is not a regular file" or the system's reason.
std::string input_file_problem(const std::filesystem::path& path, uint64_t& size);

// input_file_problem's answer for a path where nothing is (a missing OBJ material library or
// texture is a warning, where any other problem stays an error).
inline constexpr const char* no_such_file = "no such file";

}  // namespace radiant
