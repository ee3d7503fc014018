#include "scene_format/scene_format_strokes.h"

#include "scene_format/scene_format_materials.h"
#include "scene_format/scene_format_shapes.h"

namespace radiant::scene_format {

// A stroke's vertices (`least` at the fewest), width and material; its centre is its first
// vertex, so that render space moves one point.
static StrokeDesc read_stroke(BuildContext& context, const Block& block, StrokeKind kind, size_t least,
                              std::vector<AttributeName> names, Attributes& attributes) {
  expect_block_arguments(context, block, 0);
  names.insert(names.end(), {{"vertices", ""}, {"width", ""}});
  attributes = index_attributes(context, block, with_surface_names(names), block.header.text);
  const Attribute& vertices = require(context, attributes, "vertices", block.header.text);
  std::vector<float> numbers = read_numbers(context, vertices);
  if (numbers.size() % 3 != 0 || numbers.size() < 3 * least)
    fail(context, vertices.name, "'vertices' expects 3 numbers per vertex and at least " + std::to_string(least) +
                                     " vertices, got " + std::to_string(numbers.size()) + " numbers");
  StrokeDesc stroke;
  stroke.kind = kind;
  stroke.name = block.header.text + " at line " + std::to_string(block.header.line);
  stroke.center = {numbers[0], numbers[1], numbers[2]};
  for (size_t i = 0; i < numbers.size(); i += 3)
    stroke.positions.push_back(vec3{numbers[i], numbers[i + 1], numbers[i + 2]} - stroke.center);
  if (const Attribute* width = find(attributes, "width")) stroke.width = read_positive(context, *width);
  stroke.material = surface_material(context, attributes);
  return stroke;
}

void build_line_block(BuildContext& context, const Block& block) {
  Attributes attributes;
  StrokeDesc line = read_stroke(context, block, StrokeKind::lines, 2, {{"closed", ""}}, attributes);
  const Attribute* closed = find(attributes, "closed");
  if (closed && read_boolean(context, *closed)) line.positions.push_back(line.positions[0]);
  for (size_t i = 0; i + 1 < line.positions.size(); ++i) line.segments.push_back(uint32_t(i));
  context.scene.strokes.push_back(std::move(line));
}

void build_points_block(BuildContext& context, const Block& block) {
  Attributes attributes;
  context.scene.strokes.push_back(read_stroke(context, block, StrokeKind::points, 1, {}, attributes));
}

}  // namespace radiant::scene_format
