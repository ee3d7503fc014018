// tinyobjloader's warnings and errors, placed: each becomes one line `file:line: message` where
// its line can be known, `file: message` otherwise. Messages radiant already says better (a
// missing MTL library) or that are noise (a `usemtl` in an OBJ without any MTL) are dropped.
#pragma once

#include <string>
#include <vector>

#include "obj/obj_material_names.h"

namespace radiant {

struct ObjMessageSource {
  std::string file;  // the OBJ or MTL path as messages show it
  // An OBJ's `usemtl` lines, to place "material not found" (null for an MTL).
  const std::vector<MaterialNameLine>* usemtl_lines = nullptr;
  // False when no `mtllib` is named, or a named one is missing (its own warning said so): then
  // a `usemtl` naming no known material is the default material, not a problem.
  bool report_unknown_materials = true;
};

// An OBJ's `f` statement: its line number, its text and how many corners it lists.
struct FaceStatement {
  size_t line = 0;
  std::string text;
  int corners = 0;
};
// Every `f` statement of the file at `path`, in order: tinyobjloader keeps those of three
// corners or more and skips the others, so both errors and warnings find their lines here.
std::vector<FaceStatement> face_statements(const std::string& path);

// tinyobjloader's message text (lines ending in '\n') as placed one-line messages.
std::vector<std::string> placed_messages(const std::string& text, const ObjMessageSource& source);

}  // namespace radiant
