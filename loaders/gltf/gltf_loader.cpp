#include "gltf/gltf_loader.h"

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "file_access.h"
#include "gltf/gltf_animation.h"
#include "gltf/gltf_context.h"
#include "gltf/gltf_declarations.h"
#include "gltf/gltf_draco.h"
#include "gltf/gltf_files.h"
#include "gltf/gltf_materials.h"
#include "gltf/gltf_variants.h"
#include "gltf/gltf_memory.h"
#include "gltf/gltf_meshes.h"
#include "gltf/gltf_meshopt.h"
#include "gltf/gltf_nodes.h"
#include "message_text.h"
#include "scene/scene_memory.h"
#include "scene/scene_motion.h"

namespace radiant {

namespace {

// KHR_texture_basisu is read through each texture's PNG/JPEG fallback `source`; a texture
// without one is refused by name (gltf_materials.cpp).
const std::vector<std::string> supported_extensions = {
    "KHR_lights_punctual",       "KHR_materials_emissive_strength", "KHR_texture_transform",
    "KHR_materials_transmission", "KHR_materials_ior",              "KHR_materials_unlit",
    "KHR_materials_specular",     "KHR_materials_clearcoat",        "KHR_materials_sheen",
    "KHR_materials_volume",       "KHR_materials_variants",         "KHR_materials_iridescence",
    "KHR_materials_anisotropy",   "KHR_mesh_quantization",          "KHR_draco_mesh_compression",
    "EXT_texture_webp",           "EXT_meshopt_compression",        "KHR_materials_dispersion",
    "KHR_materials_pbrSpecularGlossiness", "KHR_texture_basisu", "EXT_mesh_gpu_instancing",
    "KHR_materials_diffuse_transmission"};

bool is_supported(const std::string& name) {
  return std::find(supported_extensions.begin(), supported_extensions.end(), name) != supported_extensions.end();
}

// The whole file, refused by its size before reading when tinygltf could not take it.
std::string read_gltf_file(const std::string& path, const LoadOptions& options) {
  if (check_input_file(path, path, options) > 0xFFFFFFFFull) throw LoadError(path + ": files over 4 GB are not supported");
  return read_input_file(path, path, options);
}

// Refuses what must be refused before tinygltf allocates anything, and charges the buffers it
// will allocate: each declared length, and once more for a data URI's decoded copy. A meshopt
// placeholder buffer is never allocated; its bufferViews are charged as they are decoded.
void check_declarations(const GltfDeclarations& declared, const std::string& path, const LoadOptions& options,
                        bool binary, bool uses_meshopt) {
  for (const std::string& name : declared.extensions_required)
    if (!is_supported(name))
      throw LoadError(path + ": extensionsRequired: unsupported extension " + name);
  for (size_t i = 0; i < declared.buffer_byte_lengths.size(); ++i) {
    if (uses_meshopt && is_meshopt_placeholder(declared, i, binary)) continue;
    uint64_t length = declared.buffer_byte_lengths[i];
    bool data_uri = i < declared.buffer_uris.size() && declared.buffer_uris[i] == data_uri_marker;
    charge_load(options, data_uri ? saturating_multiply(length, 2) : length,
                path + ": " + element("buffers", i) + ".byteLength");
  }
}

// tinygltf's message, placed where it names no element: "File size mismatch : PATH,
// requestedBytes N, but got M" becomes the byteLength of the buffer whose uri PATH ends with.
std::string placed_tinygltf_error(const std::string& error, const GltfDeclarations& declared) {
  const std::string mismatch = "File size mismatch : ", requested = ", requestedBytes ", got = ", but got ";
  size_t at = error.find(mismatch), numbers = error.find(requested, at), found = error.find(got, numbers);
  if (at == std::string::npos || numbers == std::string::npos || found == std::string::npos) return one_line(error);
  std::string file = error.substr(at + mismatch.size(), numbers - at - mismatch.size());
  std::string wanted = error.substr(numbers + requested.size(), found - numbers - requested.size());
  std::string held = one_line(error.substr(found + got.size()));
  held = held.substr(0, held.find_first_not_of("0123456789"));
  for (size_t i = 0; i < declared.buffer_uris.size(); ++i) {
    const std::string& uri = declared.buffer_uris[i];
    if (uri.empty() || uri == data_uri_marker || file.size() < uri.size() ||
        file.compare(file.size() - uri.size(), uri.size(), uri) != 0)
      continue;
    return element("buffers", i) + ".byteLength: " + wanted + " bytes, but '" + escaped(uri) + "' holds " + held;
  }
  return one_line(error);
}

tinygltf::Model parse(const std::string& path, const std::string& bytes, const LoadOptions& options,
                      SceneDesc& scene) {
  bool binary = bytes.compare(0, 4, "glTF") == 0;
  std::string json_chunk;
  if (binary) {
    json_chunk = glb_json_chunk(bytes, path);
    charge_load(options, json_chunk.size(), path + ": the JSON chunk");
  }
  const std::string& json = binary ? json_chunk : bytes;
  GltfJsonCounts counts = count_gltf_json(json, path);
  charge_load(options, gltf_model_bytes(counts, json.size()),
              path + ": the JSON document (" + std::to_string(counts.values) + " values)");
  GltfDeclarations declared = read_gltf_declarations(json, path);
  bool uses_meshopt = json.find(meshopt_extension) != std::string::npos;
  check_declarations(declared, path, options, binary, uses_meshopt);
  GltfFileAccess access;
  access.base_dir = std::filesystem::absolute(path).parent_path();
  access.file = path;
  access.options = &options;
  access.declarations = &declared;
  tinygltf::TinyGLTF gltf;
  install_file_access(gltf, access);
  tinygltf::Model model;
  std::string error, warning;
  // Draco files are rewritten through a second JSON tree first, charged like tinygltf's, with
  // the copy of the file it makes.
  if (json.find("KHR_draco_mesh_compression") != std::string::npos)
    charge_load(options, saturating_add(gltf_model_bytes(counts, json.size()), bytes.size()),
                path + ": the JSON document, rewritten for Draco");
  std::string with_views, with_placeholders;
  const std::string* rewritten = with_draco_index_views(bytes, binary, with_views) ? &with_views : &bytes;
  // Meshopt files are rewritten the same way, with the same charge.
  if (uses_meshopt)
    charge_load(options, saturating_add(gltf_model_bytes(counts, json.size()), rewritten->size()),
                path + ": the JSON document, rewritten for " + meshopt_extension);
  if (uses_meshopt && with_meshopt_placeholders(*rewritten, binary, declared, with_placeholders))
    rewritten = &with_placeholders;
  const std::string& document = *rewritten;
  const auto* data = reinterpret_cast<const unsigned char*>(document.data());
  bool ok = false;
  try {
    ok = binary ? gltf.LoadBinaryFromMemory(&model, &error, &warning, data, unsigned(document.size()), "")
                : gltf.LoadASCIIFromString(&model, &error, &warning, document.data(), unsigned(document.size()), "");
  } catch (const std::out_of_range& e) {
    // tinygltf 2.7 follows some indices with an unchecked at(): a primitive's material in a file
    // without materials escapes as std::out_of_range (found by the glTF fuzzer).
    throw LoadError(path + ": invalid glTF: an index refers to an element the file does not have (" +
                    one_line(e.what()) + ")");
  }
  if (!access.error.empty()) throw LoadError(access.error);
  if (!ok) throw LoadError(path + ": " + (error.empty() ? "invalid glTF" : placed_tinygltf_error(error, declared)));
  if (!warning.empty()) scene.warnings.push_back(path + ": " + one_line(warning));
  decode_buffer_view_images(model, access);
  return model;
}

// The animation writes into a document's nodes; their rest pose is put back when the scene at
// that time is made (or fails), so that the next time sampled starts from the file's own state.
struct RestPose {
  tinygltf::Model& model;
  std::vector<tinygltf::Node> nodes;
  bool saved;
  ~RestPose() {
    if (saved) model.nodes = std::move(nodes);
  }
};

}  // namespace

std::shared_ptr<GltfDocument> read_gltf_document(const std::string& path, const LoadOptions& given) {
  BudgetedLoadOptions budgeted(given);
  const LoadOptions& options = budgeted.options;
  auto document = std::make_shared<GltfDocument>();
  document->path = path;
  SceneDesc reading;  // collects the warnings of reading and decoding
  {
    std::string bytes = read_gltf_file(path, options);
    document->model = parse(path, bytes, options, reading);
  }
  GltfContext context{.model = document->model, .file = path, .options = options, .scene = reading};
  decode_meshopt_views(document->model, context);
  decode_draco_primitives(document->model, context);
  document->warnings = std::move(reading.warnings);
  return document;
}

SceneFileChoices gltf_choices(const GltfDocument& document) {
  const tinygltf::Model& model = document.model;
  SceneFileChoices choices;
  for (const tinygltf::Animation& animation : model.animations) {
    AnimationSummary summary{animation.name, 0};
    // glTF requires an input accessor's max: the last key time, read without the keys.
    for (const tinygltf::AnimationSampler& sampler : animation.samplers)
      if (sampler.input >= 0 && size_t(sampler.input) < model.accessors.size() && !model.accessors[sampler.input].maxValues.empty())
        summary.seconds = std::max(summary.seconds, model.accessors[sampler.input].maxValues[0]);
    choices.animations.push_back(summary);
  }
  LoadOptions options;
  SceneDesc unused;
  choices.material_variants = variant_names(GltfContext{.model = model, .file = document.path, .options = options, .scene = unused});
  return choices;
}

// The scene at options.animation_time alone.
static SceneDesc posed_scene(GltfDocument& document, const LoadOptions& given) {
  BudgetedLoadOptions budgeted(given);
  const LoadOptions& options = budgeted.options;
  tinygltf::Model& model = document.model;
  SceneDesc scene;
  scene.name = std::filesystem::path(document.path).stem().string();
  scene.warnings = document.warnings;
  GltfContext context{.model = model, .file = document.path, .options = options, .scene = scene};
  context.variant = selected_variant(context);
  for (const std::string& name : model.extensionsUsed)
    if (!is_supported(name)) context.warn("extension " + name + " is not supported and is ignored");
  convert_textures(context);
  convert_materials(context);
  RestPose rest_pose{model, {}, false};
  if (options.animation_time) {
    int animation = find_animation(context, options.animation);
    if (animation < 0) {
      context.warn("--time: the file has no animations; its static state is shown");
    } else {
      context.charge(saturating_multiply(model.nodes.size(), sizeof(tinygltf::Node)), "the nodes' rest pose");
      rest_pose.nodes = model.nodes;
      rest_pose.saved = true;
      apply_animation(model, context, animation, *options.animation_time);
    }
  }
  convert_meshes(context);
  convert_nodes(context);
  if (scene.degenerate_triangles_dropped > 0)
    context.warn(std::to_string(scene.degenerate_triangles_dropped) + " degenerate triangles dropped");
  return scene;
}

// Motion blur: gives `scene` the motion steps of what the animation moves while the shutter is
// open, from the scene posed at evenly spaced times across it (each charged while held).
static void add_shutter_motion(GltfDocument& document, SceneDesc& scene, const LoadOptions& options) {
  if (!options.shutter || !options.animation_time) return;
  SceneDesc unused;
  GltfContext context{.model = document.model, .file = document.path, .options = options, .scene = unused};
  int animation = find_animation(context, options.animation);
  double open = *options.animation_time + options.shutter->open, close = *options.animation_time + options.shutter->close;
  if (animation < 0 || !(close > open)) return;
  int count = motion_steps_between(context, animation, open, close);
  std::vector<SceneDesc> steps;
  steps.reserve(size_t(count));
  for (int k = 0; k < count; ++k) {
    LoadOptions at_step = options;
    at_step.animation_time = open + (close - open) * double(k) / double(count - 1);
    at_step.shutter.reset();
    steps.push_back(posed_scene(document, at_step));
    charge_load(options, scene_memory_bytes(steps.back()),
                document.path + ": the scene at shutter step " + std::to_string(k));
  }
  if (!add_motion_steps(scene, steps))
    scene.warnings.push_back(document.path + ": the scene changes its make-up while the shutter is open: no motion blur");
  // The steps are gone now; what motion they gave is the scene's own.
  for (const SceneDesc& step : steps) options.budget->release(scene_memory_bytes(step));
}

SceneDesc gltf_scene(GltfDocument& document, const LoadOptions& given) {
  BudgetedLoadOptions budgeted(given);
  SceneDesc scene = posed_scene(document, budgeted.options);
  add_shutter_motion(document, scene, budgeted.options);
  return scene;
}

SceneDesc load_gltf(const std::string& path, const LoadOptions& given) {
  BudgetedLoadOptions budgeted(given);
  std::shared_ptr<GltfDocument> document = read_gltf_document(path, budgeted.options);
  return gltf_scene(*document, budgeted.options);
}

}  // namespace radiant
