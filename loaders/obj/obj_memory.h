// What tinyobjloader builds from an OBJ or MTL file, estimated from the file's lines counted
// before it parses them, so that the memory budget can refuse first. The costs per line were
// measured (peak resident memory of tinyobjloader 2.0rc10 on files of one kind of line each);
// docs/gltf-obj.md lists them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <istream>
#include <string>

namespace radiant {

struct ObjLineCounts {
  uint64_t vertices = 0, texcoords = 0, normals = 0;  // v, vt, vn
  uint64_t faces = 0, face_corners = 0;               // f
  uint64_t elements = 0, element_corners = 0;         // l, p
  uint64_t groups = 0;                                // g, o, usemtl: each may start a shape
  uint64_t longest_line = 0;
};

// Counts the lines of an OBJ by keyword, and their corners, without keeping any of it.
ObjLineCounts count_obj_lines(std::istream& in);
// Bytes tinyobjloader's parse of such a file peaks at.
uint64_t obj_parse_bytes(const ObjLineCounts& counts);
// "3 vertices, 200000 faces": what the counts found, for messages.
std::string describe_obj_lines(const ObjLineCounts& counts);

// The `newmtl` lines of an MTL file.
uint64_t count_mtl_materials(std::istream& in);
// Bytes of `materials` parsed materials (tinyobjloader's and radiant's) from a file of
// `file_bytes` (the texture names it may hold).
uint64_t mtl_parse_bytes(uint64_t materials, uint64_t file_bytes);

// Bytes of radiant's meshes built from the parsed faces, before shading frames: each distinct
// vertex (its entry in the vertex map, its position, texcoord, normal and color) and the three
// indices of each triangle, twice for the growth of the vectors holding them.
constexpr uint64_t obj_built_vertex_bytes = 48 + 2 * (12 + 8 + 12 + 16);
constexpr uint64_t obj_built_triangle_bytes = 2 * 3 * sizeof(uint32_t);

}  // namespace radiant
