// Loader of glTF 2.0 (.gltf with external or data-URI buffers, and .glb) through tinygltf.
#pragma once

#include <tiny_gltf.h>

#include <memory>
#include <string>
#include <vector>

#include "load_options.h"
#include "scene_file_choices.h"
#include "scene/scene_desc.h"

namespace radiant {

// A glTF file read, parsed and decoded (Draco, meshopt) once, from which scenes are made at any
// time of its animations: the frames of one file share one read. Its charges to the budget
// stay for as long as it is held.
struct GltfDocument {
  std::string path;
  tinygltf::Model model;              // its nodes are in their rest pose between scenes
  std::vector<std::string> warnings;  // from reading and decoding, repeated in every scene
};

// Reads and parses `path`; throws LoadError naming the file and the JSON path of the problem.
std::shared_ptr<GltfDocument> read_gltf_document(const std::string& path, const LoadOptions& options);

// The scene of `document` at options.animation_time (its scene, variant and animation chosen
// by `options`); throws LoadError. Samples the animation into the document's nodes and puts
// them back before returning.
SceneDesc gltf_scene(GltfDocument& document, const LoadOptions& options);

// The document's animations (name, last key time) and material variants.
SceneFileChoices gltf_choices(const GltfDocument& document);

// Both at once. Throws LoadError naming the file and the JSON path of the problem.
SceneDesc load_gltf(const std::string& path, const LoadOptions& options);

}  // namespace radiant
