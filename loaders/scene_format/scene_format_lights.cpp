#include "scene_format/scene_format_lights.h"

#include "scene_format/scene_format_units.h"
#include "scene_format/scene_format_values.h"
#include "scene/enum_names.h"

namespace radiant::scene_format {

static const std::vector<AttributeName>& accepted_names(LightKind kind) {
  static const std::vector<AttributeName> ambient = {{"color", ""}};
  static const std::vector<AttributeName> directional = {{"color", ""}, {"direction", ""}};
  static const std::vector<AttributeName> point = {{"color", ""}, {"position", ""}, {"attenuation", ""}};
  static const std::vector<AttributeName> spot = {
      {"color", ""}, {"position", ""}, {"direction", ""}, {"exponent", ""}, {"attenuation", ""}};
  switch (kind) {
    case LightKind::ambient: return ambient;
    case LightKind::directional: return directional;
    case LightKind::point: return point;
    case LightKind::spot: return spot;
  }
  return ambient;
}

static LightKind light_kind(const BuildContext& context, const Block& block) {
  if (block.arguments.empty())
    fail(context, block.header, "expected a light type after '@light' (" + names_text(light_kind_names) + ")");
  expect_block_arguments(context, block, 1);
  const Token& word = block.arguments[0];
  if (std::optional<LightKind> kind = value_named(light_kind_names, word.text)) return *kind;
  fail(context, word, "unknown light type " + quote(word.text) + " (expected " + names_text(light_kind_names) + ")");
}

static void set_attenuation(const BuildContext& context, const Attribute& attribute, LightDesc& light) {
  expect_arguments(context, attribute, 3, "3 numbers (kc kl kq)");
  float* factors[3] = {&light.kc, &light.kl, &light.kq};
  for (int i = 0; i < 3; ++i) {
    *factors[i] = parse_number(context, attribute.arguments[size_t(i)]);
    if (*factors[i] < 0)
      fail(context, attribute.arguments[size_t(i)],
           "'attenuation' must not be negative, got " + shortened(attribute.arguments[size_t(i)].text));
  }
  if (light.kc == 0 && light.kl == 0 && light.kq == 0)
    fail(context, attribute.name, "'attenuation' must not be all zero");
}

void build_light_block(BuildContext& context, const Block& block) {
  LightDesc light;
  light.kind = light_kind(context, block);
  std::string what = "@light " + block.arguments[0].text;
  Attributes attributes = index_attributes(context, block, accepted_names(light.kind), what);
  color3 color = {255, 255, 255};
  if (auto* a = find(attributes, "color")) color = read_color(context, *a);
  light.intensity = light.kind == LightKind::ambient ? ambient_from_scene(color) : light_intensity_from_scene(color);
  // The classic engine's "no attenuation", unlike the inverse square LightDesc defaults to.
  light.kc = 1;
  light.kl = 0;
  light.kq = 0;
  if (auto* a = find(attributes, "attenuation")) set_attenuation(context, *a, light);
  if (light.kind == LightKind::point || light.kind == LightKind::spot)
    light.position = read_vec3(context, require(context, attributes, "position", what));
  if (light.kind == LightKind::directional || light.kind == LightKind::spot)
    light.direction = read_direction(context, require(context, attributes, "direction", what));
  if (auto* a = find(attributes, "exponent")) light.spot_exponent = read_non_negative(context, *a);
  light.use_cone = false;
  context.scene.lights.push_back(light);
}

}  // namespace radiant::scene_format
