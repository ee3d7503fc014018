// The file and image hooks given to tinygltf: every external URI goes through resolve_inside,
// and every file read and image decode is charged against LoadOptions::max_memory_bytes.
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <filesystem>
#include <string>

#include "gltf/gltf_declarations.h"
#include "load_scene.h"

namespace radiant {

struct GltfFileAccess {
  std::filesystem::path base_dir;
  std::string file;
  const LoadOptions* options = nullptr;
  const GltfDeclarations* declarations = nullptr;
  uint64_t bytes_charged = 0;  // declared buffers, then decoded images and files read
  std::string error;           // the first refusal; tinygltf only sees "not found" / "failed"
};

// Points tinygltf's file system and image decoding at `access` (which must outlive `gltf`).
void install_file_access(tinygltf::TinyGLTF& gltf, GltfFileAccess& access);

// Decodes the images stored in bufferViews once their ranges are checked; throws LoadError.
void decode_buffer_view_images(tinygltf::Model& model, GltfFileAccess& access);

// Width, height and bytes per channel of a PNG or JPEG from its header; false when unknown.
bool read_image_header(const unsigned char* bytes, size_t size, int& width, int& height,
                       int& bytes_per_channel);

}  // namespace radiant
