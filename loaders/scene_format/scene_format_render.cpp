#include "scene_format/scene_format_render.h"

#include "scene/enum_names.h"

#include "scene_format/scene_format_units.h"
#include "scene_format/scene_format_values.h"

namespace radiant::scene_format {

static const std::vector<AttributeName> render_names = {{"mode", ""},      {"spp", ""},   {"sampler", ""},
                                                        {"max-depth", ""}, {"width", ""}, {"height", ""},
                                                        {"background", ""}, {"view", ""},  {"transparent", ""},
                                                        {"filter", ""}, {"filter-width", ""}};

void build_render_block(BuildContext& context, const Block& block) {
  expect_block_arguments(context, block, 0);
  Attributes attributes = index_attributes(context, block, render_names, "@render");
  SceneSettings& settings = context.scene.settings;
  if (auto* a = find(attributes, "mode")) settings.mode = read_named(context, *a, render_mode_names);
  if (auto* a = find(attributes, "sampler")) settings.sampler = read_named(context, *a, sampler_names);
  if (auto* a = find(attributes, "spp")) settings.spp = read_integer(context, *a, 1, max_samples_per_pixel);
  if (auto* a = find(attributes, "max-depth")) settings.max_depth = read_integer(context, *a, 1, max_render_depth);
  if (auto* a = find(attributes, "width")) settings.width = read_integer(context, *a, 1, max_image_side);
  if (auto* a = find(attributes, "height")) settings.height = read_integer(context, *a, 1, max_image_side);
  if (auto* a = find(attributes, "view")) settings.view = read_named(context, *a, view_transform_names);
  if (auto* a = find(attributes, "filter")) settings.filter = read_named(context, *a, pixel_filter_names);
  if (auto* a = find(attributes, "filter-width")) {
    float width = read_positive(context, *a);
    if (width > max_filter_width)
      fail(context, a->arguments[0], "filter-width " + a->arguments[0].text + " is wider than 64 pixels");
    settings.filter_width = width;
  }
  if (auto* a = find(attributes, "transparent")) settings.transparent = read_boolean(context, *a);
  if (auto* a = find(attributes, "background")) context.scene.environment.color = radiance_from_scene(read_color(context, *a));
}

}  // namespace radiant::scene_format
