// Entry point of the loaders: a scene file in, a validated SceneDesc out.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

#include "scene/scene_desc.h"

namespace radiant {

// A scene that cannot be loaded. what() is one line that names the place: `file:line:col: ...`
// for text formats, `file: meshes[2].primitives[0].indices: ...` for glTF.
struct LoadError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct LoadOptions {
  bool allow_external_files = false;  // let URIs and includes leave the scene's folder
  size_t max_memory_bytes = 0;        // refuse files declaring more; 0 = default_max_memory()
  int gltf_scene = -1;                // glTF scene index; -1 = the file's default scene
};

// Joins a library's multi-line message into one line ("; " between non-empty lines).
std::string one_line(const std::string& text);

// Text from a file (a URI, a name) made safe to show inside a one-line message: control bytes,
// NUL included, are written as \n, \r, \t or \xNN instead of cutting or breaking the line.
std::string escaped(const std::string& text);

// A quarter of physical memory: the default for LoadOptions::max_memory_bytes.
size_t default_max_memory();

// Loads by extension: .scene (or "-" for stdin, read as .scene), .gltf, .glb, .obj.
// Throws LoadError.
SceneDesc load_scene(const std::string& path, const LoadOptions& options = {});

}  // namespace radiant
