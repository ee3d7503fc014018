// File names as Windows exporters write them in OBJ and MTL files (`map_Kd .\tex.jpg`,
// `mtllib sub\m.mtl`): a backslash is a folder separator. Confinement to the OBJ's folder
// (resolve_inside) applies after this translation, unchanged.
#pragma once

#include <istream>
#include <map>
#include <string>

namespace radiant {

// `name` with every backslash read as a folder separator.
std::string portable_path(const std::string& name);

// The `mtllib` names of an OBJ as written, keyed by what tinyobjloader asks for: it reads a
// backslash as an escape and drops it ("sub\m.mtl" becomes "subm.mtl"). Written names keep an
// escaped space ("my\ file.mtl") and turn any other backslash into a separator.
std::map<std::string, std::string> mtllib_names(std::istream& in);

// "UTF-16 big-endian" or "UTF-16 little-endian" when a file starting with `first_bytes` (two or
// more) is UTF-16 text (a byte order mark, or ASCII with NUL bytes between), else "".
std::string utf16_byte_order(const std::string& first_bytes);

}  // namespace radiant
