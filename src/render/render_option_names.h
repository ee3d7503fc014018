// The words the command line and the image metadata use for the render options' enums: one
// table per enum, read both ways with scene/enum_names.h's name_of and value_named.
#pragma once

#include <utility>

#include "render/render_options.h"
#include "scene/enum_names.h"

namespace radiant {

inline constexpr std::pair<PathBatching, const char*> path_batching_names[] = {
    {PathBatching::none, "none"}, {PathBatching::camera_rays, "camera"}, {PathBatching::all_rays, "all"}};
inline constexpr std::pair<ShardSplit, const char*> shard_split_names[] = {
    {ShardSplit::tiles, "tiles"}, {ShardSplit::samples, "samples"}, {ShardSplit::both, "both"}};
inline constexpr std::pair<EnvironmentPreset, const char*> environment_preset_names[] = {
    {EnvironmentPreset::studio, "studio"}, {EnvironmentPreset::white, "white"}, {EnvironmentPreset::none, "none"}};

}  // namespace radiant
