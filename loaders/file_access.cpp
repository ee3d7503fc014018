#include "file_access.h"

#include "load_scene.h"

namespace radiant {
// Placeholder so that callers link until path safety lands; it refuses every include.
std::filesystem::path resolve_inside(const std::filesystem::path&, const std::string& uri, bool,
                                     const std::string& where) {
  throw LoadError(where + ": cannot include '" + uri + "': path resolution is not implemented yet");
}
}  // namespace radiant
