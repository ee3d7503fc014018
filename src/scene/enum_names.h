// The words the command line, `radiant info` and the file formats use for the scene's enums:
// one table per enum, read both ways.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>

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

// The names of `table` as "a, b, c or d", for messages.
template <class Enum, size_t N>
std::string names_text(const std::pair<Enum, const char*> (&table)[N]) {
  std::string text;
  for (size_t i = 0; i < N; ++i) text += std::string(i == 0 ? "" : i + 1 == N ? " or " : ", ") + table[i].second;
  return text;
}

}  // namespace radiant
