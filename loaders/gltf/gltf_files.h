// The file and image hooks given to tinygltf: every external URI goes through resolve_inside and
// check_input_file, and every file read and image decode is charged to the load's memory budget.
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

#include "gltf/gltf_declarations.h"
#include "load_options.h"

namespace radiant {

struct GltfFileAccess {
  std::filesystem::path base_dir;
  std::string file;
  const LoadOptions* options = nullptr;
  const GltfDeclarations* declarations = nullptr;
  std::map<std::string, std::string> uri_of_path;  // resolved path -> the URI as tinygltf asked
  std::string error;  // the first refusal; tinygltf only sees "not found" / "failed"
};

// Points tinygltf's file system and image decoding at `access` (which must outlive `gltf`).
void install_file_access(tinygltf::TinyGLTF& gltf, GltfFileAccess& access);

// Decodes the images stored in bufferViews once their ranges are checked; throws LoadError.
void decode_buffer_view_images(tinygltf::Model& model, GltfFileAccess& access);

// Width, height and bytes per channel of a PNG or JPEG from its header; false when unknown.
bool read_image_header(const unsigned char* bytes, size_t size, int& width, int& height,
                       int& bytes_per_channel);

// False when JPEG data ends before its end-of-image marker: stb_image decodes what is missing as
// zeros, so a cut-off file would give texels that were never in it.
bool jpeg_is_complete(const unsigned char* bytes, size_t size);

}  // namespace radiant
