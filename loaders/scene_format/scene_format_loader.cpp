#include "scene_format/scene_format_loader.h"

namespace radiant {
SceneDesc load_scene_format(std::istream&, const std::string& display_name, const std::string&,
                            const LoadOptions&) {
  throw LoadError(display_name + ": .scene loading is not implemented yet");
}
}  // namespace radiant
