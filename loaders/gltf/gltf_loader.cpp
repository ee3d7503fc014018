#include "gltf/gltf_loader.h"

namespace radiant {
SceneDesc load_gltf(const std::string& path, const LoadOptions&) {
  throw LoadError(path + ": glTF loading is not implemented yet");
}
}  // namespace radiant
