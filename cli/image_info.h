// `radiant info IMAGE [--json]`: an image file's size, channels, pixel type and the metadata
// radiant recorded in it (image/render_metadata.h).
#pragma once

#include <ostream>
#include <string>

namespace radiant::cli {

// Whether `path` names an image rather than a scene: not a scene's extension (.scene, .gltf,
// .glb, .obj) nor standard input, and an image's signature (PNG, OpenEXR, TIFF, JPEG, Radiance
// HDR) or an image's extension.
bool is_image_path(const std::string& path);

// Prints what `path` holds, as text or one JSON object. Throws std::runtime_error "path: why"
// for a file that cannot be read as an image.
void print_image_info(std::ostream& out, const std::string& path, bool json);

}  // namespace radiant::cli
