// The words the command line, `radiant info` and the file formats use for the scene's enums:
// one table per enum, read both ways.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "scene/scene_desc.h"

namespace radiant {

inline constexpr std::pair<Projection, const char*> projection_names[] = {{Projection::perspective, "perspective"},
                                                                         {Projection::orthographic, "orthographic"},
                                                                         {Projection::equirectangular, "equirect"},
                                                                         {Projection::fisheye, "fisheye"}};
inline constexpr std::pair<LightKind, const char*> light_kind_names[] = {{LightKind::ambient, "ambient"},
                                                                        {LightKind::directional, "directional"},
                                                                        {LightKind::point, "point"},
                                                                        {LightKind::spot, "spot"}};
inline constexpr std::pair<RenderMode, const char*> render_mode_names[] = {{RenderMode::auto_select, "auto"},
                                                                          {RenderMode::whitted, "whitted"},
                                                                          {RenderMode::path, "path"},
                                                                          {RenderMode::naive, "naive"}};
inline constexpr std::pair<SamplerKind, const char*> sampler_names[] = {{SamplerKind::grid, "grid"},
                                                                       {SamplerKind::random, "random"},
                                                                       {SamplerKind::jittered, "jittered"},
                                                                       {SamplerKind::sobol, "sobol"}};
inline constexpr std::pair<ViewTransform, const char*> view_transform_names[] = {
    {ViewTransform::standard, "standard"}, {ViewTransform::linear, "linear"}, {ViewTransform::filmic, "filmic"},
    {ViewTransform::agx, "agx"},           {ViewTransform::neutral, "neutral"}, {ViewTransform::aces, "aces"}};
inline constexpr std::pair<PixelFilterKind, const char*> pixel_filter_names[] = {
    {PixelFilterKind::box, "box"},           {PixelFilterKind::triangle, "triangle"},
    {PixelFilterKind::gaussian, "gaussian"}, {PixelFilterKind::mitchell, "mitchell"},
    {PixelFilterKind::blackman_harris, "blackman-harris"}};
inline constexpr std::pair<LightSampler, const char*> light_sampler_names[] = {
    {LightSampler::automatic, "auto"}, {LightSampler::power, "power"}, {LightSampler::bvh, "bvh"}};
inline constexpr std::pair<TextureFilterMode, const char*> texture_filter_names[] = {
    {TextureFilterMode::point, "point"}, {TextureFilterMode::bilinear, "bilinear"},
    {TextureFilterMode::trilinear, "trilinear"}};

// The name of `value` in `table` ("" when it has none).
template <class Enum, size_t N>
constexpr const char* name_of(const std::pair<Enum, const char*> (&table)[N], Enum value) {
  for (const auto& [e, name] : table)
    if (e == value) return name;
  return "";
}

// The value named `name` in `table`, if any.
template <class Enum, size_t N>
constexpr std::optional<Enum> value_named(const std::pair<Enum, const char*> (&table)[N], std::string_view name) {
  for (const auto& [e, n] : table)
    if (name == n) return e;
  return std::nullopt;
}

// `names` as "a, b, c or d", for messages.
inline std::string choices_text(const std::vector<std::string>& names) {
  std::string text;
  for (size_t i = 0; i < names.size(); ++i) text += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return text;
}

// The names of `table` as "a, b, c or d", for messages.
template <class Enum, size_t N>
std::string names_text(const std::pair<Enum, const char*> (&table)[N]) {
  std::vector<std::string> names;
  for (const auto& entry : table) names.push_back(entry.second);
  return choices_text(names);
}

}  // namespace radiant
