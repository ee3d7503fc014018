// The one exception every loader and the scene validation throw for a file they refuse.
#pragma once

#include <stdexcept>

namespace radiant {

// A scene that cannot be loaded. what() is one line that names the place: `file:line:col: ...`
// for text formats, `file: meshes[2].primitives[0].indices: ...` for glTF.
struct LoadError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace radiant
