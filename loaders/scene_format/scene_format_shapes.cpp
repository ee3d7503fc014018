#include "scene_format/scene_format_shapes.h"

#include <cmath>

#include "scene_format/scene_format_materials.h"

namespace radiant::scene_format {

std::vector<AttributeName> with_surface_names(std::vector<AttributeName> names) {
  const std::vector<AttributeName>& surface = surface_attribute_names();
  names.insert(names.end(), surface.begin(), surface.end());
  return names;
}

// Reads the block's attributes and starts a shape with its material.
static ShapeDesc start_shape(BuildContext& context, const Block& block, ShapeKind kind,
                             const std::vector<AttributeName>& names, Attributes& attributes) {
  expect_block_arguments(context, block, 0);
  attributes = index_attributes(context, block, with_surface_names(names), block.header.text);
  ShapeDesc shape;
  shape.kind = kind;
  shape.material = surface_material(context, attributes);
  return shape;
}

void build_sphere_block(BuildContext& context, const Block& block) {
  Attributes attributes;
  ShapeDesc shape = start_shape(context, block, ShapeKind::sphere, {{"center", "p"}, {"radius", "r"}}, attributes);
  shape.center = read_vec3(context, require(context, attributes, "center", "@sphere"));
  shape.radius = read_positive(context, require(context, attributes, "radius", "@sphere"));
  context.scene.shapes.push_back(shape);
}

void build_plane_block(BuildContext& context, const Block& block) {
  Attributes attributes;
  ShapeDesc shape = start_shape(context, block, ShapeKind::plane, {{"point", "p"}, {"normal", "n"}}, attributes);
  shape.center = read_vec3(context, require(context, attributes, "point", block.header.text));
  shape.axis = read_direction(context, require(context, attributes, "normal", block.header.text));
  context.scene.shapes.push_back(shape);
}

static const std::vector<AttributeName> cylinder_names = {{"base", ""}, {"axis", ""}, {"height", ""},
                                                          {"from", ""}, {"to", ""},   {"radius", ""}};

// The end-points form: base at `from`, axis towards `to`.
static void set_cylinder_ends(const BuildContext& context, const Attributes& attributes, ShapeDesc& shape) {
  for (const char* name : {"base", "axis", "height"})
    if (const Attribute* other = find(attributes, name))
      fail(context, other->name, quote(other->name.text) + " cannot be combined with 'from' and 'to'");
  vec3 from = read_vec3(context, require(context, attributes, "from", "@cylinder"));
  const Attribute& to = require(context, attributes, "to", "@cylinder");
  vec3 offset = read_vec3(context, to) - from;
  if (max_component(abs(offset)) == 0) fail(context, to.name, "'to' must differ from 'from'");
  if (!std::isfinite(length(offset))) fail(context, to.name, "'to' is too far from 'from'");
  shape.center = from;
  shape.height = length(offset);
  shape.axis = offset / shape.height;
}

void build_cylinder_block(BuildContext& context, const Block& block) {
  Attributes attributes;
  ShapeDesc shape = start_shape(context, block, ShapeKind::cylinder, cylinder_names, attributes);
  if (find(attributes, "from") || find(attributes, "to")) {
    set_cylinder_ends(context, attributes, shape);
  } else {
    shape.center = read_vec3(context, require(context, attributes, "base", "@cylinder"));
    shape.axis = read_direction(context, require(context, attributes, "axis", "@cylinder"));
    shape.height = read_positive(context, require(context, attributes, "height", "@cylinder"));
  }
  shape.radius = read_positive(context, require(context, attributes, "radius", "@cylinder"));
  context.scene.shapes.push_back(shape);
}

void build_tube_block(BuildContext& context, const Block& block) {
  Attributes attributes;
  ShapeDesc shape =
      start_shape(context, block, ShapeKind::tube, {{"point", ""}, {"axis", ""}, {"radius", ""}}, attributes);
  shape.center = read_vec3(context, require(context, attributes, "point", "@tube"));
  shape.axis = read_direction(context, require(context, attributes, "axis", "@tube"));
  shape.radius = read_positive(context, require(context, attributes, "radius", "@tube"));
  context.scene.shapes.push_back(shape);
}

}  // namespace radiant::scene_format
