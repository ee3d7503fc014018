// glTF points and lines (POINTS, LINES, LINE_LOOP, LINE_STRIP) and the .scene format's @line and
// @points: each mode loads as the strokes it draws, placed by its node, counted by `info`.
#include <doctest/doctest.h>

#include "load_scene.h"
#include "loaders/gltf_builder.h"
#include "scene/scene_summary.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// Four vertices on a unit square, drawn by one primitive of each mode beside a triangle pair, as
// Khronos' MeshPrimitiveModes does; the node moves them 10 along z.
SceneDesc load_every_mode(ScratchDir& dir) {
  GltfBuilder b = quad_builder();
  b.floats({1, 0, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 0, 0, 1, 1}, "VEC4", 4);  // 2: COLOR_0
  std::string primitives;
  for (int mode : {0, 1, 2, 3, 4})
    primitives += std::string(primitives.empty() ? "" : ",") +
                  "{\"attributes\":{\"POSITION\":0,\"COLOR_0\":2},\"mode\":" + std::to_string(mode) +
                  (mode == 4 ? ",\"indices\":1}" : "}");
  std::string body = "\"meshes\":[{\"primitives\":[" + primitives + "]}],\"nodes\":[{\"mesh\":0,"
                     "\"translation\":[0,0,10]}],\"scenes\":[{\"nodes\":[0]}]";
  return load_scene(dir.write("modes.gltf", b.gltf(body)).string());
}

vec3 world_vertex(const StrokeDesc& stroke, size_t i) { return stroke.center + stroke.positions.at(i); }

}  // namespace

TEST_CASE("gltf strokes: POINTS, LINES, LINE_LOOP and LINE_STRIP load as the points and segments they draw") {
  ScratchDir dir("gltf-strokes");
  SceneDesc scene = load_every_mode(dir);
  CHECK(scene.warnings.empty());
  CHECK(scene.meshes.size() == 1);  // the TRIANGLES primitive
  REQUIRE(scene.strokes.size() == 4);
  const StrokeDesc &points = scene.strokes[0], &lines = scene.strokes[1], &loop = scene.strokes[2],
                   &strip = scene.strokes[3];
  CHECK(points.kind == StrokeKind::points);
  CHECK(points.primitive_count() == 4);
  CHECK(world_vertex(points, 2) == vec3{1, 1, 10});
  CHECK(points.colors.at(1).y == 1);
  CHECK(points.colors.at(1).x == 0);
  CHECK(lines.kind == StrokeKind::lines);
  CHECK(lines.segments == std::vector<uint32_t>{0, 2});  // (0,1) and (2,3)
  CHECK(loop.segments == std::vector<uint32_t>{0, 1, 2, 3});  // back to the first vertex
  CHECK(world_vertex(loop, 4) == vec3{0, 0, 10});
  CHECK(strip.segments == std::vector<uint32_t>{0, 1, 2});
  CHECK(strip.width == 0);  // glTF has no width: --line-width decides
  SceneSummary summary = summarize_scene(scene);
  CHECK(summary.points == 4);
  CHECK(summary.line_segments == 2 + 4 + 3);
  CHECK(summary.triangles == 2);
}

TEST_CASE("gltf strokes: a line of one vertex has nothing to draw and is skipped with a warning") {
  ScratchDir dir("gltf-stroke-empty");
  GltfBuilder b;
  b.floats({0, 0, 0, 1, 0, 0}, "VEC3", 3);
  b.indices({0});
  std::string body = "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,\"mode\":3},"
                     "{\"attributes\":{\"POSITION\":0},\"mode\":0}]}],\"nodes\":[{\"mesh\":0}],"
                     "\"scenes\":[{\"nodes\":[0]}]";
  SceneDesc scene = load_scene(dir.write("one.gltf", b.gltf(body)).string());
  REQUIRE(scene.warnings.size() == 1);
  CHECK(scene.warnings[0] == dir.file("one.gltf").string() + ": meshes[0].primitives[0]: no line segments; primitive skipped");
  REQUIRE(scene.strokes.size() == 1);
  CHECK(scene.strokes[0].kind == StrokeKind::points);
}

TEST_CASE("scene format: @line and @points give strokes with their width and material") {
  ScratchDir dir("scene-strokes");
  std::string path = dir.write("s.scene",
                               "@line\nvertices 0 0 0  1 0 0  1 1 0\nclosed true\nwidth 0.1\nkd 1 0 0\n"
                               "@points\nvertices 5 5 5  6 6 6\nkd 0 1 0\n")
                         .string();
  SceneDesc scene = load_scene(path);
  REQUIRE(scene.strokes.size() == 2);
  const StrokeDesc& line = scene.strokes[0];
  CHECK(line.kind == StrokeKind::lines);
  CHECK(line.segments == std::vector<uint32_t>{0, 1, 2});
  CHECK(world_vertex(line, 3) == vec3{0, 0, 0});
  CHECK(line.width == doctest::Approx(0.1));
  CHECK(scene.strokes[1].width == 0);
  CHECK(world_vertex(scene.strokes[1], 1) == vec3{6, 6, 6});
  CHECK(scene.strokes[0].material != scene.strokes[1].material);
  std::string bad = dir.write("bad.scene", "@line\nvertices 0 0 0\n").string();
  CHECK_THROWS_WITH_AS(load_scene(bad),
                       (bad + ":2:1: 'vertices' expects 3 numbers per vertex and at least 2 vertices, got 3 numbers").c_str(),
                       LoadError);
}
