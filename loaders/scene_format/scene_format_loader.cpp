#include "scene_format/scene_format_loader.h"

#include <utility>

#include "scene_format/scene_format_camera.h"
#include "scene_format/scene_format_context.h"
#include "scene_format/scene_format_lights.h"
#include "scene_format/scene_format_materials.h"
#include "scene_format/scene_format_mesh.h"
#include "scene_format/scene_format_polygons.h"
#include "scene_format/scene_format_render.h"
#include "scene_format/scene_format_shapes.h"
#include "scene_format/scene_format_strokes.h"

namespace radiant {

using namespace scene_format;

using BlockBuilder = void (*)(BuildContext&, const Block&);

// Every block kind of the format and what builds it; the order is the one listed in messages.
static const std::pair<const char*, BlockBuilder> block_builders[] = {
    {"viewer", build_viewer_block},     {"camera", build_camera_block},     {"light", build_light_block},
    {"material", build_material_block}, {"sphere", build_sphere_block},     {"wall", build_plane_block},
    {"plane", build_plane_block},       {"triangle", build_triangle_block}, {"polygon", build_polygon_block},
    {"cylinder", build_cylinder_block}, {"tube", build_tube_block},         {"mesh", build_mesh_block},
    {"line", build_line_block},         {"points", build_points_block},     {"render", build_render_block},
};

static void build_block(BuildContext& context, const Block& block) {
  std::string kind = block.kind(), expected;
  for (const auto& [name, builder] : block_builders) {
    if (kind == name) return builder(context, block);
    expected += (expected.empty() ? "@" : ", @") + std::string(name);
  }
  fail(context, block.header, "unknown block " + quote(block.header.text) + " (expected " + expected + ")");
}

// `scene NAME...`: the name is the rest of the line, words joined by single spaces.
static std::string scene_name(const std::vector<Token>& scene_line) {
  std::string name;
  for (size_t i = 1; i < scene_line.size(); ++i) name += (i > 1 ? " " : "") + scene_line[i].text;
  return name;
}

SceneDesc load_scene_format(std::istream& in, const std::string& display_name, const std::string& base_dir,
                            const LoadOptions& given) {
  BudgetedLoadOptions budgeted(given);
  const LoadOptions& options = budgeted.options;
  SceneText text = read_scene_text(in, display_name, *options.budget);
  BuildContext context;
  context.display_name = display_name;
  context.base_dir = base_dir;
  context.options = options;
  context.scene.name = scene_name(text.scene_line);
  for (const Block& block : text.blocks) build_block(context, block);
  return std::move(context.scene);
}

}  // namespace radiant
