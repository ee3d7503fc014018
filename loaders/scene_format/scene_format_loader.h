// Loader of radiant's `.scene` text format (docs/scene-format.md), including the older format.
#pragma once

#include <istream>
#include <string>

#include "load_options.h"
#include "scene/scene_desc.h"

namespace radiant {

// Parses `in`; `display_name` prefixes messages (`display_name:line:col: ...`), `base_dir`
// resolves includes. Throws LoadError.
SceneDesc load_scene_format(std::istream& in, const std::string& display_name,
                            const std::string& base_dir, const LoadOptions& options);

}  // namespace radiant
