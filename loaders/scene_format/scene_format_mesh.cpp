#include "scene_format/scene_format_mesh.h"

#include <cmath>

#include "file_access.h"
#include "obj/obj_loader.h"
#include "scene_format/scene_format_materials.h"
#include "scene_format/scene_format_shapes.h"
#include "scene_format/scene_format_values.h"

namespace radiant::scene_format {

static const std::vector<AttributeName> mesh_names = {
    {"file", ""}, {"translate", ""}, {"rotate", ""}, {"scale", ""}, {"matrix", ""}};

static mat4 read_rotation(const BuildContext& context, const Attribute& attribute) {
  expect_arguments(context, attribute, 4, "4 numbers (axis x y z, degrees)");
  vec3 axis;
  for (int i = 0; i < 3; ++i) axis[i] = parse_number(context, attribute.arguments[size_t(i)]);
  if (max_component(abs(axis)) == 0) fail(context, attribute.name, "'rotate' axis must not be zero-length");
  return rotation_axis(axis / max_component(abs(axis)), parse_number(context, attribute.arguments[3]));
}

static mat4 read_scaling(const BuildContext& context, const Attribute& attribute) {
  size_t count = attribute.arguments.size();
  if (count != 1 && count != 3)
    fail(context, attribute.name, "'scale' expects 1 or 3 numbers, got " + std::to_string(count));
  vec3 factors;
  for (int i = 0; i < 3; ++i) {
    const Token& token = attribute.arguments[count == 1 ? 0 : size_t(i)];
    factors[i] = parse_number(context, token);
    if (factors[i] == 0) fail(context, token, "'scale' must not be zero");
  }
  return scaling(factors);
}

static mat4 read_matrix(const BuildContext& context, const Attribute& attribute) {
  std::vector<float> numbers = read_numbers(context, attribute);
  if (numbers.size() != 12 && numbers.size() != 16)
    fail(context, attribute.name, "'matrix' expects 12 or 16 numbers (row-major), got " + std::to_string(numbers.size()));
  if (numbers.size() == 16 && !(numbers[12] == 0 && numbers[13] == 0 && numbers[14] == 0 && numbers[15] == 1))
    fail(context, attribute.name, "'matrix' must be affine (last row 0 0 0 1)");
  mat4 matrix;
  for (int i = 0; i < 12; ++i) matrix.m[i / 4][i % 4] = numbers[size_t(i)];
  mat4 inverse;
  if (!inverse_affine(matrix, inverse)) fail(context, attribute.name, "'matrix' is singular");
  if (!inverse_survives_float(matrix))
    fail(context, attribute.name, "'matrix' is too close to singular to invert in single precision, as ray tracing must");
  return matrix;
}

mat4 mesh_transform(const BuildContext& context, const Block& block) {
  Attributes attributes = index_attributes(context, block, with_surface_names(mesh_names), "@mesh");
  if (const Attribute* matrix = find(attributes, "matrix")) {
    for (const char* name : {"translate", "rotate", "scale"})
      if (const Attribute* other = find(attributes, name))
        fail(context, other->name, quote(other->name.text) + " cannot be combined with 'matrix'");
    return read_matrix(context, *matrix);
  }
  mat4 transform;
  if (auto* a = find(attributes, "translate")) transform = translation(read_vec3(context, *a));
  if (auto* a = find(attributes, "rotate")) transform = transform * read_rotation(context, *a);
  if (auto* a = find(attributes, "scale")) transform = transform * read_scaling(context, *a);
  return transform;
}

void build_mesh_block(BuildContext& context, const Block& block) {
  expect_block_arguments(context, block, 0);
  Attributes attributes = index_attributes(context, block, with_surface_names(mesh_names), "@mesh");
  const Attribute& file = require(context, attributes, "file", "@mesh");
  std::string uri = read_word(context, file);
  mat4 transform = mesh_transform(context, block);
  int material_override = has_surface_attributes(attributes) ? surface_material(context, attributes) : -1;
  const Token& where = file.arguments[0];
  std::string place = context.display_name + ":" + std::to_string(where.line) + ":" + std::to_string(where.column);
  std::filesystem::path path = resolve_inside(context.base_dir, uri, context.options.allow_external_files, place);
  check_input_file(path, place + ": " + quote(uri), context.options);
  try {
    append_obj(context.scene, path.string(), transform, context.options, material_override);
  } catch (const LoadError& error) {
    fail(context, where, "in included " + quote(uri) + ": " + error.what());
  }
}

}  // namespace radiant::scene_format
