// Resolving files a scene refers to (buffers, images, OBJ includes) without leaving its folder.
#pragma once

#include <filesystem>
#include <string>

namespace radiant {

// Resolves `uri` (relative, percent-decoded by the caller) against `base_dir`. Unless
// `allow_external`, refuses absolute paths, `..` escapes and symlinks that lead outside
// `base_dir`, throwing LoadError with `where` (e.g. "scene.gltf: images[2].uri") in the message.
std::filesystem::path resolve_inside(const std::filesystem::path& base_dir, const std::string& uri,
                                     bool allow_external, const std::string& where);

}  // namespace radiant
