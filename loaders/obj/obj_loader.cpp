#include "obj/obj_loader.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "file_access.h"
#include "message_text.h"
#include "text_lines.h"
#include "obj/obj_material_names.h"
#include "obj/obj_materials.h"
#include "obj/obj_messages.h"
#include "obj/obj_memory.h"
#include "obj/obj_numbers.h"
#include "obj/obj_paths.h"
#include "memory/input_file.h"
#include "scene/polygon_triangulation.h"
#include "scene/mesh_ops.h"
#include "scene/scene_memory.h"

namespace radiant {

namespace {

// `mtllib` files resolve inside the OBJ's folder like every other file. A missing one is a
// warning (its materials fall back to the default one, as Blender's and assimp's importers do);
// any other refusal stays an error.
struct MtlReader : tinyobj::MaterialReader {
  std::filesystem::path base_dir;
  const std::string& file;
  const LoadOptions& options;
  std::map<std::string, std::string> written_names;  // tinyobjloader's name -> as written
  std::vector<std::string>& warnings;
  std::string refusal;
  bool missing_library = false;
  MtlReader(std::filesystem::path base, const std::string& f, const LoadOptions& o,
            std::map<std::string, std::string> names, std::vector<std::string>& w)
      : base_dir(std::move(base)), file(f), options(o), written_names(std::move(names)), warnings(w) {}
  bool operator()(const std::string& asked, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* names, std::string* /*warn: placed here, where the MTL is known*/,
                  std::string* err) override {
    auto written = written_names.find(asked);
    std::string name = portable_path(written == written_names.end() ? asked : written->second);
    try {
      auto path = resolve_inside(base_dir, name, options.allow_external_files, file + ": mtllib");
      std::string label = file + ": mtllib '" + escaped(name) + "'";
      uint64_t size = 0;
      if (input_file_problem(path, size) == no_such_file) {
        warnings.push_back(label + ": " + no_such_file + "; its materials are replaced by the default material");
        missing_library = true;
        return false;
      }
      size = check_input_file(path, label, options);
      std::ifstream in(path);
      if (!in) throw LoadError(label + ": cannot open");
      std::string mtl_file = (std::filesystem::path(file).parent_path() / name).string();
      check_line_lengths(in, mtl_file);  // before any line is read whole
      in.clear();
      in.seekg(0);
      check_mtl_numbers(in, mtl_file);
      in.clear();
      in.seekg(0);
      // tinyobjloader keeps about 2 KB a material: count them before it parses any.
      uint64_t count = count_mtl_materials(in);
      charge_load(options, mtl_parse_bytes(count, size), label + ": " + std::to_string(count) + " materials");
      in.clear();
      in.seekg(0);
      MaterialNameFilter filter(in, "newmtl");
      std::istream named(&filter);
      std::string mtl_warnings;
      tinyobj::LoadMtl(names, materials, &named, &mtl_warnings, err);
      for (std::string& warning : placed_messages(mtl_warnings, {mtl_file}))
        warnings.push_back(std::move(warning));
      return true;
    } catch (const LoadError& error) {
      if (refusal.empty()) refusal = error.what();
      return false;
    }
  }
};

struct ObjData {
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
};

// tinyobjloader reads bytes: UTF-16 text would parse as nothing at all.
void check_not_utf16(std::istream& in, const std::string& path) {
  std::string start(2, '\0');
  in.read(start.data(), 2);
  start.resize(size_t(in.gcount()));
  std::string encoding = utf16_byte_order(start);
  if (!encoding.empty())
    throw LoadError(path + ": the file is " + encoding + " text; radiant reads OBJ files as ASCII or UTF-8 "
                    "(convert it, e.g. iconv -f UTF-16 -t UTF-8)");
}

ObjData parse_obj(const std::string& path, const LoadOptions& options, std::vector<std::string>& warnings) {
  check_input_file(path, path, options);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw LoadError(path + ": cannot open");
  check_not_utf16(in, path);
  auto rewind = [&] {
    in.clear();
    in.seekg(0);
  };
  rewind();
  check_line_lengths(in, path);  // before any line is read whole
  rewind();
  check_obj_numbers(in, path);
  rewind();
  // What tinyobjloader builds (about 170 bytes for an eight-byte face line) is charged from the
  // counted lines before it parses any.
  ObjLineCounts counts = count_obj_lines(in);
  charge_load(options, obj_parse_bytes(counts), path + ": " + describe_obj_lines(counts));
  rewind();
  std::map<std::string, std::string> libraries = mtllib_names(in);
  rewind();
  ObjData data;
  bool names_libraries = !libraries.empty();
  MtlReader reader(std::filesystem::absolute(path).parent_path(), path, options, std::move(libraries), warnings);
  MaterialNameFilter filter(in, "usemtl");
  std::istream named(&filter);
  std::string warning, error;
  bool ok = tinyobj::LoadObj(&data.attrib, &data.shapes, &data.materials, &warning, &error, &named, &reader, false, false);
  if (!reader.refusal.empty()) throw LoadError(reader.refusal);
  ObjMessageSource source{path, &filter.named_lines(), names_libraries && !reader.missing_library};
  if (!ok || !error.empty()) {
    std::vector<std::string> errors = placed_messages(error, source);
    throw LoadError(errors.empty() ? path + ": invalid OBJ" : errors[0]);
  }
  for (std::string& placed : placed_messages(warning, source)) warnings.push_back(std::move(placed));
  for (tinyobj::material_t& material : data.materials) material.name = decode_material_name(material.name);
  return data;
}

// Builds one mesh per material, sharing a vertex wherever (position, texcoord, normal) repeat.
struct MeshBuilder {
  MeshDesc mesh;
  std::unordered_map<uint64_t, uint32_t> vertices;  // packed index triple -> vertex
  bool all_normals = true;
  bool smoothed = false;  // some face is in a smoothing group (`s 1`, ...)
  size_t vertices_charged = 0;  // vertices the memory budget has been charged for
};

uint64_t pack(const tinyobj::index_t& i) {
  return (uint64_t(uint32_t(i.vertex_index)) << 42) ^ (uint64_t(uint32_t(i.texcoord_index + 1)) << 21) ^
         uint64_t(uint32_t(i.normal_index + 1));
}

// The `f` lines tinyobjloader keeps (three corners or more), to report errors as file:line:col.
std::vector<FaceStatement> kept_face_lines(const std::string& path) {
  std::vector<FaceStatement> faces = face_statements(path);
  std::erase_if(faces, [](const FaceStatement& f) { return f.corners < 3; });
  return faces;
}

// "file:line:col" of corner `corner` of face `face` (counted over the whole file).
std::string corner_location(const std::string& path, const std::vector<FaceStatement>& faces, size_t face, size_t corner) {
  if (face >= faces.size()) return path;
  const std::string& text = faces[face].text;
  size_t at = text.find('f');
  for (size_t k = 0; k <= corner && at != std::string::npos; ++k) {
    at = text.find_first_not_of(" \t", text.find_first_of(" \t", at));
  }
  std::string column = at == std::string::npos ? "" : ":" + std::to_string(at + 1);
  return path + ":" + std::to_string(faces[face].line) + column;
}

void check_corner(const std::string& location, const tinyobj::attrib_t& a, const tinyobj::index_t& i) {
  auto fail = [&](const char* what, int index, size_t count) {
    std::string plural = what == std::string("vertex") ? "vertices" : what + std::string("s");
    throw LoadError(location + ": " + what + " index " + std::to_string(index + 1) + " out of range (" +
                    std::to_string(count) + " " + plural + ")");
  };
  size_t positions = a.vertices.size() / 3, texcoords = a.texcoords.size() / 2, normals = a.normals.size() / 3;
  if (i.vertex_index < 0 || size_t(i.vertex_index) >= positions) fail("vertex", i.vertex_index, positions);
  if (i.texcoord_index < -1 || (i.texcoord_index >= 0 && size_t(i.texcoord_index) >= texcoords))
    fail("texcoord", i.texcoord_index, texcoords);
  if (i.normal_index < -1 || (i.normal_index >= 0 && size_t(i.normal_index) >= normals))
    fail("normal", i.normal_index, normals);
}

uint32_t add_corner(MeshBuilder& builder, const tinyobj::attrib_t& a, const tinyobj::index_t& i) {
  auto [it, inserted] = builder.vertices.try_emplace(pack(i), uint32_t(builder.mesh.positions.size()));
  if (!inserted) return it->second;
  MeshDesc& mesh = builder.mesh;
  const auto& v = a.vertices;
  mesh.positions.push_back({v[i.vertex_index * 3], v[i.vertex_index * 3 + 1], v[i.vertex_index * 3 + 2]});
  // OBJ has v up, glTF (and radiant's sampler) v down.
  vec2 uv = i.texcoord_index >= 0 ? vec2{a.texcoords[i.texcoord_index * 2], 1 - a.texcoords[i.texcoord_index * 2 + 1]}
                                  : vec2{0, 0};
  mesh.texcoords0.push_back(uv);
  const auto& n = a.normals;
  builder.all_normals = builder.all_normals && i.normal_index >= 0;
  mesh.normals.push_back(i.normal_index >= 0 ? vec3{n[i.normal_index * 3], n[i.normal_index * 3 + 1], n[i.normal_index * 3 + 2]}
                                             : vec3{0, 0, 0});
  // `v x y z r g b`: tinyobjloader keeps the colors only when every vertex has them.
  const auto& c = a.colors;
  if (c.size() == v.size())
    mesh.colors.push_back({c[i.vertex_index * 3], c[i.vertex_index * 3 + 1], c[i.vertex_index * 3 + 2], 1});
  return it->second;
}

// Charges the indices build_meshes is about to make from the parsed faces, and the work space of
// triangulating the largest polygon.
void charge_mesh_indices(const std::string& path, const ObjData& data, const LoadOptions& options) {
  uint64_t triangles = 0, largest = 0;
  for (const tinyobj::shape_t& shape : data.shapes)
    for (unsigned count : shape.mesh.num_face_vertices) {
      triangles += count > 2 ? count - 2 : 0;
      largest = std::max<uint64_t>(largest, count);
    }
  charge_load(options, saturating_multiply(triangles, obj_built_triangle_bytes),
              path + ": " + std::to_string(triangles) + " triangles");
  charge_load(options, saturating_multiply(largest, polygon_triangulation_bytes_per_corner),
              path + ": triangulating a polygon of " + std::to_string(largest) + " corners");
}

// How many corners repeat a vertex is known only while building: a mesh's vertices are charged
// as they come, the charge doubling like the vectors that hold them (at least 1024 at a time).
void charge_vertices(MeshBuilder& builder, size_t more, const std::string& path, const LoadOptions& options) {
  if (builder.mesh.positions.size() + more <= builder.vertices_charged) return;
  size_t chunk = std::max({more, builder.vertices_charged, size_t(1024)});
  charge_load(options, saturating_multiply(chunk, obj_built_vertex_bytes),
              path + ": " + std::to_string(builder.vertices_charged + chunk) + " distinct vertices");
  builder.vertices_charged += chunk;
}

// The meshes by MTL material index (-1 = none), and the polygons that cross themselves.
struct BuiltMeshes {
  std::map<int, MeshBuilder> builders;
  size_t crossing_polygons = 0;
  std::string first_crossing;  // file:line:col of the first
};

// Polygons are triangulated by ear clipping (concave ones too; triangles stay triangles).
BuiltMeshes build_meshes(const std::string& path, const ObjData& data, const LoadOptions& options) {
  BuiltMeshes built;
  std::vector<FaceStatement> lines;  // read only when a message needs a location
  auto location = [&](size_t face, size_t corner) {
    if (lines.empty()) lines = kept_face_lines(path);
    return corner_location(path, lines, face, corner);
  };
  size_t face_in_file = 0;
  std::vector<uint32_t> corners;
  std::vector<vec3> corner_positions;
  for (const tinyobj::shape_t& shape : data.shapes) {
    const auto& faces = shape.mesh;
    size_t first = 0;
    for (size_t f = 0; f < faces.num_face_vertices.size(); ++f, ++face_in_file) {
      size_t count = faces.num_face_vertices[f];
      int material = f < faces.material_ids.size() ? faces.material_ids[f] : -1;
      if (material >= int(data.materials.size())) material = -1;
      MeshBuilder& builder = built.builders[material];
      if (f < faces.smoothing_group_ids.size() && faces.smoothing_group_ids[f] != 0) builder.smoothed = true;
      for (size_t k = 0; k < count; ++k) {
        try {
          check_corner(path, data.attrib, faces.indices[first + k]);
        } catch (const LoadError&) {
          check_corner(location(face_in_file, k), data.attrib, faces.indices[first + k]);
        }
      }
      charge_vertices(builder, count, path, options);
      corners.resize(count);
      corner_positions.resize(count);
      for (size_t k = 0; k < count; ++k) {
        corners[k] = add_corner(builder, data.attrib, faces.indices[first + k]);
        corner_positions[k] = builder.mesh.positions[corners[k]];
      }
      PolygonTriangles triangles = triangulate_polygon(corner_positions);
      for (uint32_t corner : triangles.corners) builder.mesh.indices.push_back(corners[corner]);
      if (!triangles.simple && built.crossing_polygons++ == 0) built.first_crossing = location(face_in_file, 0);
      first += count;
    }
  }
  return built;
}

bool has_texcoords(const ObjData& data) { return !data.attrib.texcoords.empty(); }

}  // namespace

void append_obj(SceneDesc& scene, const std::string& path, const mat4& transform, const LoadOptions& given,
                int material_override) {
  BudgetedLoadOptions budgeted(given);
  const LoadOptions& options = budgeted.options;
  ObjData data = parse_obj(path, options, scene.warnings);
  std::vector<int> materials(data.materials.size(), material_override);
  if (material_override < 0) {
    ObjTextureLoader textures{scene, std::filesystem::absolute(path).parent_path(), path, options, {}};
    for (size_t m = 0; m < data.materials.size(); ++m) {
      materials[m] = int(scene.materials.size());
      scene.materials.push_back(convert_mtl_material(textures, data.materials[m]));
    }
  }
  size_t dropped = 0;
  charge_mesh_indices(path, data, options);
  BuiltMeshes built = build_meshes(path, data, options);
  if (built.crossing_polygons > 0)
    scene.warnings.push_back(built.first_crossing + ": " + std::to_string(built.crossing_polygons) +
                             " polygons cross themselves (this one first); their triangles may overlap");
  for (auto& [material, builder] : built.builders) {
    MeshDesc& mesh = builder.mesh;
    if (material >= 0) {
      mesh.material = materials[material];
      mesh.name = data.materials[material].name;
    } else if (material_override >= 0) {
      mesh.material = material_override;
    } else {
      // Faces without `usemtl` get a plain grey diffuse material.
      MaterialDesc plain;
      plain.name = "default";
      plain.kd = {0.8f, 0.8f, 0.8f};
      mesh.material = int(scene.materials.size());
      scene.materials.push_back(plain);
    }
    if (mesh.name.empty()) mesh.name = std::filesystem::path(path).stem().string();
    dropped += drop_degenerate_triangles(mesh);
    if (mesh.indices.empty()) continue;
    if (!has_texcoords(data)) mesh.texcoords0.clear();
    bool normal_mapped = scene.materials[mesh.material].normal_texture.valid() && !mesh.texcoords0.empty();
    charge_load(options, shading_frame_bytes(mesh, normal_mapped), path + ": " + mesh.name);
    // Without vn, OBJ shades faces flat unless they are in a smoothing group; smoothed faces get
    // area-weighted normals (across group boundaries too: groups are not told apart).
    if (builder.all_normals) {
      if (size_t bad = repair_normals(mesh))
        scene.warnings.push_back(path + ": " + std::to_string(bad) + " zero-length normals recomputed");
    } else if (builder.smoothed) {
      generate_normals(mesh);
    } else {
      shade_flat(mesh, normal_mapped);
    }
    if (normal_mapped && mesh.tangents.empty()) generate_tangents(mesh);
    scene.instances.push_back({int(scene.meshes.size()), transform, mesh.name, {}});
    scene.meshes.push_back(std::move(mesh));
  }
  if (dropped > 0) scene.warnings.push_back(path + ": " + std::to_string(dropped) + " degenerate triangles dropped");
  scene.degenerate_triangles_dropped += dropped;
}

SceneDesc load_obj(const std::string& path, const LoadOptions& options) {
  SceneDesc scene;
  scene.name = std::filesystem::path(path).stem().string();
  append_obj(scene, path, mat4{}, options);  // a scene without light is reported by render and info, flags known
  return scene;
}

}  // namespace radiant
