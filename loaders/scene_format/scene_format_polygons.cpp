#include "scene_format/scene_format_polygons.h"

#include <cmath>
#include <sstream>

#include "scene_format/scene_format_materials.h"
#include "scene_format/scene_format_shapes.h"
#include "scene/polygon_triangulation.h"

namespace radiant::scene_format {

// ---------------------------------------------------------------- planarity

// Double precision: the checks compare small differences of coordinates that may be large.
struct Point {
  double x, y, z;
};
static Point operator-(Point a, Point b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
static double dot(Point a, Point b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static Point cross(Point a, Point b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
static double length(Point a) { return std::sqrt(dot(a, a)); }

// Relative tolerances, as fractions of the polygon's size (largest distance from its centroid).
constexpr double planar_tolerance = 1e-4;

static std::string number_text(double value) {
  std::ostringstream text;
  text.precision(3);
  text << value;
  return text.str();
}

static std::string vertex_text(size_t index) { return "vertex " + std::to_string(index + 1); }

// Newell's normal: robust for nearly planar polygons; its length is twice the area.
static Point newell_normal(const std::vector<Point>& points) {
  Point normal = {0, 0, 0};
  for (size_t i = 0; i < points.size(); ++i) {
    Point c = cross(points[i], points[(i + 1) % points.size()]);
    normal = {normal.x + c.x, normal.y + c.y, normal.z + c.z};
  }
  return normal;
}

std::string polygon_defect(const std::vector<vec3>& vertices) {
  size_t n = vertices.size();
  Point centroid = {0, 0, 0};
  for (vec3 v : vertices) centroid = {centroid.x + v.x / double(n), centroid.y + v.y / double(n), centroid.z + v.z / double(n)};
  std::vector<Point> points;
  double size = 0;
  for (vec3 v : vertices) {
    points.push_back(Point{v.x, v.y, v.z} - centroid);
    size = std::max(size, length(points.back()));
  }
  if (size == 0) return "has all its vertices at one point";
  Point normal = newell_normal(points);
  double normal_length = length(normal);
  if (normal_length <= 1e-10 * size * size) return "has zero area (its vertices are collinear)";
  normal = {normal.x / normal_length, normal.y / normal_length, normal.z / normal_length};
  for (size_t i = 0; i < n; ++i) {
    double distance = std::abs(dot(points[i], normal));
    if (distance > planar_tolerance * size)
      return "is not planar (" + vertex_text(i) + " is " + number_text(distance) + " away from the mean plane)";
  }
  return "";
}

// ---------------------------------------------------------------- blocks

static std::vector<vec3> read_vertices(const BuildContext& context, const Attribute& attribute) {
  std::vector<float> numbers = read_numbers(context, attribute);
  if (numbers.size() % 3 != 0)
    fail(context, attribute.name, "'vertices' expects 3 numbers per vertex, got " + std::to_string(numbers.size()) + " numbers");
  if (numbers.size() < 9)
    fail(context, attribute.name, "'vertices' expects at least 3 vertices, got " + std::to_string(numbers.size() / 3));
  std::vector<vec3> vertices;
  for (size_t i = 0; i < numbers.size(); i += 3) vertices.push_back({numbers[i], numbers[i + 1], numbers[i + 2]});
  return vertices;
}

// Appends the triangles of the polygon to the mesh that holds the faces of `material`.
static void add_triangles(BuildContext& context, int material, const std::vector<vec3>& vertices,
                          const std::vector<uint32_t>& corners) {
  SceneDesc& scene = context.scene;
  auto [found, inserted] = context.polygon_mesh_by_material.emplace(material, int(scene.meshes.size()));
  if (inserted) {
    MeshDesc mesh;
    mesh.name = "faces of material " + scene.materials[size_t(material)].name;
    mesh.material = material;
    scene.meshes.push_back(mesh);
    scene.instances.push_back({found->second, mat4{}, mesh.name, {}});
  }
  MeshDesc& mesh = scene.meshes[size_t(found->second)];
  uint32_t first = uint32_t(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), vertices.begin(), vertices.end());
  for (uint32_t corner : corners) mesh.indices.push_back(first + corner);
}

static void build_face_block(BuildContext& context, const Block& block, bool is_triangle) {
  expect_block_arguments(context, block, 0);
  Attributes attributes = index_attributes(context, block, with_surface_names({{"vertices", ""}}), block.header.text);
  const Attribute& attribute = require(context, attributes, "vertices", block.header.text);
  std::vector<vec3> vertices = read_vertices(context, attribute);
  if (is_triangle && vertices.size() != 3)
    fail(context, attribute.name, "'vertices' of @triangle expects 9 numbers, got " + std::to_string(vertices.size() * 3));
  std::string defect = polygon_defect(vertices);
  if (!defect.empty()) fail(context, attribute.name, (is_triangle ? "triangle " : "polygon ") + defect);
  PolygonTriangles triangles = triangulate_polygon(vertices);
  if (!triangles.simple) fail(context, attribute.name, "polygon crosses itself (its edges cross or it winds around twice)");
  add_triangles(context, surface_material(context, attributes), vertices, triangles.corners);
}

void build_triangle_block(BuildContext& context, const Block& block) { build_face_block(context, block, true); }

void build_polygon_block(BuildContext& context, const Block& block) { build_face_block(context, block, false); }

}  // namespace radiant::scene_format
