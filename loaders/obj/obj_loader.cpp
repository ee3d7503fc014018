#include "obj/obj_loader.h"

namespace radiant {
void append_obj(SceneDesc&, const std::string& path, const mat4&, const LoadOptions&, int) {
  throw LoadError(path + ": OBJ loading is not implemented yet");
}
SceneDesc load_obj(const std::string& path, const LoadOptions&) {
  throw LoadError(path + ": OBJ loading is not implemented yet");
}
}  // namespace radiant
