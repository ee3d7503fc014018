// Entry point of the loaders: a scene file in, a validated SceneDesc out.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "memory/memory_budget.h"
#include "scene/scene_desc.h"

namespace radiant {

// A scene that cannot be loaded. what() is one line that names the place: `file:line:col: ...`
// for text formats, `file: meshes[2].primitives[0].indices: ...` for glTF.
struct LoadError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct LoadOptions {
  bool allow_external_files = false;  // let URIs and includes leave the scene's folder
  // Charged for everything loading allocates, before it is allocated (the command shares it
  // with the render). Null: the load makes its own budget of `max_memory_bytes`.
  MemoryBudget* budget = nullptr;
  size_t max_memory_bytes = 0;  // the limit of that own budget; 0 = default_memory_limit()
  int gltf_scene = -1;          // glTF scene index; -1 = the file's default scene
  std::string material_variant;  // KHR_materials_variants: the variant to use; "" = the default materials
  // glTF: sample `animation` (a name or index; "" = the first) at this time in seconds; unset =
  // the file's static state (docs/gltf-obj.md, "Animation").
  std::optional<double> animation_time;
  std::string animation;
  // Every file the load reads is appended here (load_scene sets it; SceneDesc::input_files).
  std::vector<std::string>* files_read = nullptr;
};

// Charges `bytes` for `what` (a file and a place) to options.budget, which must be set; throws
// LoadError with the budget's one-line refusal.
void charge_load(const LoadOptions& options, uint64_t bytes, const std::string& what);

// `given` with a budget for loaders called directly (tests, fuzzers): its own budget when it has
// one, else a new one of given.max_memory_bytes held here. Not copyable: `options.budget` may
// point into it.
struct BudgetedLoadOptions {
  std::optional<MemoryBudget> own_budget;
  LoadOptions options;
  explicit BudgetedLoadOptions(const LoadOptions& given);
  BudgetedLoadOptions(const BudgetedLoadOptions&) = delete;
  BudgetedLoadOptions& operator=(const BudgetedLoadOptions&) = delete;
};

// The most bytes of a file's text (or of a library's message, which may echo it: a whole data
// URI) that one message quotes; longer text is cut, saying its length.
constexpr size_t max_message_excerpt = 300;

// Joins a library's multi-line message into one line ("; " between non-empty lines), at most
// max_message_excerpt bytes of it.
std::string one_line(const std::string& text);

// Text from a file (a URI, a name) made safe to show inside a one-line message: control bytes,
// NUL included, are written as \n, \r, \t or \xNN instead of cutting or breaking the line, and
// at most max_message_excerpt bytes of it are shown.
std::string escaped(const std::string& text);

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

// What a file offers to choose from besides cameras and lights, for `radiant info`.
struct AnimationSummary {
  std::string name;
  double seconds = 0;  // the last key time of its channels
};
struct SceneFileChoices {
  std::vector<AnimationSummary> animations;   // --animation, --time, --frame
  std::vector<std::string> material_variants;  // --variant (KHR_materials_variants)
};
// Empty for formats without animations or variants. Throws LoadError for a malformed list.
SceneFileChoices scene_file_choices(const SceneFile& file);

// The scene of `file` at options.animation_time, validated, as load_scene gives it: afterwards
// the budget holds this scene's size besides the file's. Throws LoadError.
SceneDesc scene_from_file(SceneFile& file, const LoadOptions& options);

}  // namespace radiant
