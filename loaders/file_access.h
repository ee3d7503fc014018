// Resolving files a scene refers to (buffers, images, OBJ includes) without leaving its folder,
// and the one check every file a loader reads passes before it is opened.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace radiant {

struct LoadOptions;

// Resolves `uri` (relative, percent-decoded by the caller) against `base_dir`. Unless
// `allow_external`, refuses absolute paths, `..` escapes and symlinks that lead outside
// `base_dir`, throwing LoadError with `where` (e.g. "scene.gltf: images[2].uri") in the message.
std::filesystem::path resolve_inside(const std::filesystem::path& base_dir, const std::string& uri,
                                     bool allow_external, const std::string& where);

// Every file a loader reads passes here before it is opened: anything but a regular file (a
// FIFO would block forever) is refused with LoadError "`label`: no such file" / "is a directory"
// / "is not a regular file". Returns the size. `label` names the file and the place, e.g.
// "scene.gltf: images[0].uri 'x.png'".
// The file is recorded in options.files_read.
uint64_t check_input_file(const std::filesystem::path& path, const std::string& label, const LoadOptions& options);

// check_input_file, then the whole file, its size charged to the load's budget before reading.
std::string read_input_file(const std::filesystem::path& path, const std::string& label, const LoadOptions& options);

}  // namespace radiant
