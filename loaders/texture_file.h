// An 8-bit texture read from an image file through OpenImageIO (the OBJ loader's map_* files,
// glTF's EXT_texture_webp images), charged to the load's budget from the header before decoding.
#pragma once

#include <filesystem>
#include <string>

#include "load_options.h"
#include "scene/scene_desc.h"

namespace radiant {

// The image at `path` with up to 4 of its channels as 8-bit texels. Messages start with `where`
// and name the image as `name` (as the file wrote it); throws LoadError.
ImageDesc read_texture_file(const std::filesystem::path& path, const std::string& where, const std::string& name,
                            const LoadOptions& options);

}  // namespace radiant
