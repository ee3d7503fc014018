#include "obj/obj_memory.h"

#include <tiny_obj_loader.h>

#include "memory/memory_budget.h"
#include "scene/scene_desc.h"

namespace radiant {

namespace {

// Measured per line, with about a third added for where vector growth lands: a vertex 18.5
// bytes, a texcoord 10, a normal 18, a face 96 + 25 per corner, a line or point 40 + 30 per
// corner, a group's shape about 200.
constexpr uint64_t vertex_cost = 24, texcoord_cost = 16, normal_cost = 24;
constexpr uint64_t face_cost = 128, element_cost = 64, corner_cost = 32, group_cost = 512;

bool is_line_end(int c) { return c == '\n' || c == '\r'; }
bool is_blank(int c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

// Calls `line(keyword, tokens after it, length)` for every line of `in`; keywords longer than
// six characters are cut (no OBJ or MTL keyword is).
template <typename LineFunction>
void for_each_line(std::istream& in, LineFunction line) {
  std::streambuf* buffer = in.rdbuf();
  if (!buffer) return;
  std::string keyword;
  uint64_t tokens = 0, length = 0;
  bool in_token = false;
  for (int c = buffer->sbumpc();; c = buffer->sbumpc()) {
    if (c == std::char_traits<char>::eof() || is_line_end(c)) {
      if (length > 0) line(keyword, tokens == 0 ? 0 : tokens - 1, length);
      if (c == std::char_traits<char>::eof()) return;
      keyword.clear(), tokens = 0, length = 0, in_token = false;
      continue;
    }
    ++length;
    if (is_blank(c)) {
      in_token = false;
      continue;
    }
    if (!in_token) ++tokens, in_token = true;
    if (tokens == 1 && keyword.size() < 7) keyword += char(c);
  }
}

}  // namespace

ObjLineCounts count_obj_lines(std::istream& in) {
  ObjLineCounts counts;
  for_each_line(in, [&](const std::string& keyword, uint64_t arguments, uint64_t length) {
    counts.longest_line = std::max(counts.longest_line, length);
    if (keyword == "v") ++counts.vertices;
    else if (keyword == "vt") ++counts.texcoords;
    else if (keyword == "vn") ++counts.normals;
    else if (keyword == "f") ++counts.faces, counts.face_corners += arguments;
    else if (keyword == "l" || keyword == "p") ++counts.elements, counts.element_corners += arguments;
    else if (keyword == "g" || keyword == "o" || keyword == "usemtl") ++counts.groups;
  });
  return counts;
}

uint64_t obj_parse_bytes(const ObjLineCounts& c) {
  uint64_t bytes = c.vertices * vertex_cost + c.texcoords * texcoord_cost + c.normals * normal_cost;
  bytes += c.faces * face_cost + c.elements * element_cost + (c.face_corners + c.element_corners) * corner_cost;
  return bytes + c.groups * group_cost + 2 * c.longest_line;  // the line and its tokens, copied once each
}

std::string describe_obj_lines(const ObjLineCounts& c) {
  std::string text;
  auto add = [&](uint64_t count, const char* what) {
    if (count > 0) text += (text.empty() ? "" : ", ") + std::to_string(count) + " " + what;
  };
  add(c.vertices, "vertices");
  add(c.texcoords, "texcoords");
  add(c.normals, "normals");
  add(c.faces, "faces");
  add(c.elements, "lines and points");
  add(c.groups, "groups");
  return text.empty() ? "the file" : text;
}

uint64_t count_mtl_materials(std::istream& in) {
  uint64_t materials = 0;
  for_each_line(in, [&](const std::string& keyword, uint64_t, uint64_t) { materials += keyword == "newmtl"; });
  return materials;
}

uint64_t mtl_parse_bytes(uint64_t materials, uint64_t file_bytes) {
  // Measured: 1.95 KB a material in tinyobjloader (its struct and its name in a map).
  uint64_t per_material = 2 * sizeof(tinyobj::material_t) + sizeof(MaterialDesc);
  return saturating_add(saturating_multiply(materials, per_material), file_bytes);
}

}  // namespace radiant
