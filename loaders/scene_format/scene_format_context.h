// State shared by the .scene block builders while they turn blocks into a SceneDesc.
#pragma once

#include <map>
#include <string>

#include "load_options.h"
#include "scene/scene_desc.h"
#include "scene_format/scene_format_syntax.h"

namespace radiant::scene_format {

struct BuildContext {
  std::string display_name;  // prefixes every message
  std::string base_dir;      // resolves `@mesh file` includes
  LoadOptions options;
  SceneDesc scene;
  std::map<std::string, int> materials_by_name;  // `@material NAME` blocks seen so far
  std::map<int, int> polygon_mesh_by_material;   // triangles and polygons share a mesh per material
  int default_material = -1;                     // created when a shape names no material
};

// Throws LoadError at `where`, prefixed with the file name.
[[noreturn]] inline void fail(const BuildContext& context, const Token& where, const std::string& message) {
  fail_at(context.display_name, where, message);
}

}  // namespace radiant::scene_format
