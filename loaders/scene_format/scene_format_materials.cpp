#include "scene_format/scene_format_materials.h"

#include "scene_format/scene_format_units.h"

namespace radiant::scene_format {

static const std::vector<AttributeName> phong_names = {{"kd", ""}, {"ks", ""},        {"ka", ""},
                                                       {"kr", ""}, {"kt", ""},        {"shininess", ""},
                                                       {"ior", ""}, {"emission", ""}};
static const std::vector<AttributeName> older_names = {{"c", ""}, {"e", ""}, {"s", ""}};

const std::vector<AttributeName>& surface_attribute_names() {
  static const std::vector<AttributeName> names = [] {
    std::vector<AttributeName> all = {{"material", ""}};
    all.insert(all.end(), phong_names.begin(), phong_names.end());
    all.insert(all.end(), older_names.begin(), older_names.end());
    return all;
  }();
  return names;
}

// A .scene material before its attributes: ka = 1 as in the classic engine, and ior = 1 because
// the classic engine passed transmitted rays straight through.
static MaterialDesc scene_material(const std::string& name) {
  MaterialDesc material;
  material.name = name;
  material.model = MaterialModel::phong;
  material.ka = {1, 1, 1};
  material.ior = 1;
  return material;
}

static int add_material(BuildContext& context, MaterialDesc material) {
  context.scene.materials.push_back(std::move(material));
  return int(context.scene.materials.size()) - 1;
}

static void apply_phong_attributes(const BuildContext& context, const Attributes& attributes,
                                   MaterialDesc& material) {
  if (auto* a = find(attributes, "kd")) material.kd = read_color(context, *a);
  if (auto* a = find(attributes, "ks")) material.ks = read_color(context, *a);
  if (auto* a = find(attributes, "ka")) material.ka = read_color(context, *a);
  if (auto* a = find(attributes, "kr")) material.kr = read_color(context, *a);
  if (auto* a = find(attributes, "kt")) material.kt = read_color(context, *a);
  if (auto* a = find(attributes, "shininess")) material.shininess = read_non_negative(context, *a);
  if (auto* a = find(attributes, "ior")) material.ior = read_positive(context, *a);
  if (auto* a = find(attributes, "emission")) material.emission = radiance_from_scene(read_color(context, *a));
}

void build_material_block(BuildContext& context, const Block& block) {
  if (block.arguments.empty()) fail(context, block.header, "expected a material name after '@material'");
  expect_block_arguments(context, block, 1);
  const Token& name = block.arguments[0];
  if (context.materials_by_name.count(name.text))
    fail(context, name, "material " + quote(name.text) + " is already defined");
  Attributes attributes = index_attributes(context, block, phong_names, "@material");
  MaterialDesc material = scene_material(name.text);
  apply_phong_attributes(context, attributes, material);
  context.materials_by_name[name.text] = add_material(context, std::move(material));
}

// The older format: c is a 0-255 color; smooth surfaces are diffuse, others are mirrors; e scales
// c into emitted radiance.
static int older_material(BuildContext& context, const Attributes& attributes) {
  color3 color = {255, 255, 255};
  float emittance = 0;
  bool smooth = true;
  if (auto* a = find(attributes, "c")) {
    color = read_color(context, *a);
    // A 0-255 colour above 255 would reflect more light than arrives.
    for (size_t i = 0; i < a->arguments.size(); ++i)
      if (color[int(a->arguments.size() == 1 ? 0 : i)] > 255)
        fail(context, a->arguments[i], "'c' is a colour from 0 to 255, got " + shortened(a->arguments[i].text));
  }
  if (auto* a = find(attributes, "e")) emittance = read_non_negative(context, *a);
  if (auto* a = find(attributes, "s")) smooth = read_boolean(context, *a);
  color3 reflectance = color / 255.0f;
  MaterialDesc material = scene_material("older format (line " + std::to_string(attributes.block->header.line) + ")");
  material.kd = smooth ? reflectance : color3{0, 0, 0};
  material.ka = material.kd;
  material.kr = smooth ? color3{0, 0, 0} : reflectance;
  material.emission = reflectance * emittance;  // finite: c is at most 255, e a finite float
  return add_material(context, std::move(material));
}

static const Attribute* first_present(const Attributes& attributes, const std::vector<AttributeName>& names) {
  for (const AttributeName& name : names)
    if (const Attribute* attribute = find(attributes, name.name)) return attribute;
  return nullptr;
}

static int default_material(BuildContext& context) {
  if (context.default_material < 0) {
    MaterialDesc material = scene_material("default");
    material.kd = {1, 1, 1};
    context.default_material = add_material(context, std::move(material));
  }
  return context.default_material;
}

static int named_material(const BuildContext& context, const Attribute& attribute) {
  std::string name = read_word(context, attribute);
  auto found = context.materials_by_name.find(name);
  if (found == context.materials_by_name.end())
    fail(context, attribute.arguments[0],
         "unknown material " + quote(name) + " (define it with '@material " + name + "' before this line)");
  return found->second;
}

bool has_surface_attributes(const Attributes& attributes) {
  return first_present(attributes, surface_attribute_names()) != nullptr;
}

int surface_material(BuildContext& context, const Attributes& attributes) {
  const Attribute* older = first_present(attributes, older_names);
  const Attribute* phong = first_present(attributes, phong_names);
  const Attribute* named = find(attributes, "material");
  if (older && (phong || named)) {
    const Attribute* other = phong ? phong : named;
    fail(context, older->name, "older-format " + quote(older->name.text) + " cannot be combined with " +
                                   quote(other->name.text) + " on one shape");
  }
  if (older) return older_material(context, attributes);
  int base = named ? named_material(context, *named) : -1;
  if (!phong) return base >= 0 ? base : default_material(context);
  // Inline attributes override the named material in a copy of their own.
  MaterialDesc material = base >= 0 ? context.scene.materials[size_t(base)] : scene_material("");
  material.name = "inline (line " + std::to_string(attributes.block->header.line) + ")";
  apply_phong_attributes(context, attributes, material);
  return add_material(context, std::move(material));
}

}  // namespace radiant::scene_format
