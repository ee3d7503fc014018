// Entry point of the loaders: a scene file in, a validated SceneDesc out.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "load_options.h"
#include "scene_file_choices.h"
#include "scene/load_error.h"
#include "scene/scene_desc.h"

namespace radiant {

// Loads by extension: .scene (or "-" for stdin, read as .scene), .gltf, .glb, .obj. Afterwards
// the budget holds the loaded scene's own size: what loading needed only while it ran is given
// back. Throws LoadError.
SceneDesc load_scene(const std::string& path, const LoadOptions& options = {});

struct GltfDocument;  // gltf/gltf_loader.h

// A scene file read once, to make scenes from at many animation times (`render --frames`): a
// glTF's parsed and decoded document, or any other format's loaded scene, which time does not
// change. What reading it charged to the budget stays charged while it is held.
struct SceneFile {
  std::string path;
  std::shared_ptr<GltfDocument> gltf;      // .gltf and .glb
  std::shared_ptr<const SceneDesc> scene;  // the other formats
  std::vector<std::string> files_read;
};

// Reads (and for glTF parses) `path`; options.budget must be set. Throws LoadError.
SceneFile read_scene_file(const std::string& path, const LoadOptions& options);

// Empty for formats without animations or variants. Throws LoadError for a malformed list.
SceneFileChoices scene_file_choices(const SceneFile& file);

// The scene of `file` at options.animation_time, validated, as load_scene gives it: afterwards
// the budget holds this scene's size besides the file's. Throws LoadError.
SceneDesc scene_from_file(SceneFile& file, const LoadOptions& options);

}  // namespace radiant
