// glTF primitives: modes, component types, normalized integers, strides, sparse accessors.
#include <doctest/doctest.h>

#include "loaders/gltf_builder.h"
#include "accel/scene_accel.h"
#include "load_scene.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

static SceneDesc load_text(const std::string& text, const std::string& name = "scene.gltf") {
  ScratchDir dir("gltf-geometry");
  return load_scene(dir.write(name, text).string());
}

static std::string one_primitive(const std::string& primitive) {
  return "\"meshes\":[{\"primitives\":[" + primitive + "]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]";
}

TEST_CASE("gltf: an indexed quad without NORMAL becomes one mesh shaded flat (no vertex normals)") {
  SceneDesc scene = load_text(quad_builder().gltf(one_primitive("{\"attributes\":{\"POSITION\":0},\"indices\":1}")));
  REQUIRE(scene.meshes.size() == 1);
  CHECK(scene.meshes[0].indices == std::vector<uint32_t>{0, 1, 2, 0, 2, 3});
  CHECK(scene.meshes[0].normals.empty());
  CHECK(scene.instances.size() == 1);
  CHECK(scene.materials.size() == 1);  // the glTF default material
  CHECK(scene.materials[0].name == "glTF default");
  // A UTF-8 byte order mark is allowed.
  std::string text = quad_builder().gltf(one_primitive("{\"attributes\":{\"POSITION\":0},\"indices\":1}"));
  CHECK(load_text("\xEF\xBB\xBF" + text).meshes.size() == 1);
}

TEST_CASE("gltf: without NORMAL a folded pair of triangles shades each face with its own normal, with NORMAL it interpolates") {
  // Two triangles sharing the edge from (1,0,0) to (0,1,0): one flat in z = 0, one folded up.
  GltfBuilder b;
  b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 1}, "VEC3", 3);
  b.indices({0, 1, 2, 1, 3, 2});
  b.floats({0, 0, 1, 0, 0.6f, 0.8f, 0, 0.6f, 0.8f, 0, 0.6f, 0.8f}, "VEC3", 3);
  // Straight down onto the flat triangle, next to the shared edge.
  Ray ray = {{0.45f, 0.45f, 5}, {0, 0, -1}};
  SUBCASE("flat (glTF 3.7.2.1: clients must calculate flat normals)") {
    SceneDesc scene = load_text(b.gltf(one_primitive("{\"attributes\":{\"POSITION\":0},\"indices\":1}")));
    auto accel = build_scene_accel(scene);
    SurfaceHit hit = make_surface_hit(*accel, ray, intersect_nearest(*accel, ray));
    CHECK(hit.geometric_normal.z == doctest::Approx(1));
    CHECK(hit.shading_normal.x == hit.geometric_normal.x);
    CHECK(hit.shading_normal.y == hit.geometric_normal.y);
    CHECK(hit.shading_normal.z == hit.geometric_normal.z);
  }
  SUBCASE("authored normals are interpolated") {
    SceneDesc scene = load_text(b.gltf(one_primitive("{\"attributes\":{\"POSITION\":0,\"NORMAL\":2},\"indices\":1}")));
    auto accel = build_scene_accel(scene);
    SurfaceHit hit = make_surface_hit(*accel, ray, intersect_nearest(*accel, ray));
    CHECK(hit.geometric_normal.z == doctest::Approx(1));
    CHECK(hit.shading_normal.y > 0.5f);  // mostly the tilted normals of the edge's vertices
  }
}

TEST_CASE("gltf: triangle strips alternate winding and fans share the first vertex") {
  GltfBuilder b;
  b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 2, 0}, "VEC3", 3);
  SceneDesc strip = load_text(b.gltf(one_primitive("{\"attributes\":{\"POSITION\":0},\"mode\":5}")));
  CHECK(strip.meshes[0].indices == std::vector<uint32_t>{0, 1, 2, 1, 3, 2, 2, 3, 4});
  SceneDesc fan = load_text(b.gltf(one_primitive("{\"attributes\":{\"POSITION\":0},\"mode\":6}")));
  CHECK(fan.meshes[0].indices == std::vector<uint32_t>{1, 2, 0, 2, 3, 0, 3, 4, 0});
}

TEST_CASE("gltf: lines load beside triangles and radiant info counts their segments") {
  GltfBuilder b = quad_builder();
  std::string prims = "{\"attributes\":{\"POSITION\":0},\"mode\":1},{\"attributes\":{\"POSITION\":0},\"indices\":1}";
  SceneDesc scene = load_text(b.gltf(one_primitive(prims)));
  CHECK(scene.meshes.size() == 1);
  CHECK(scene.warnings.empty());
  REQUIRE(scene.strokes.size() == 1);
  CHECK(scene.strokes[0].segments.size() == 2);
  ScratchDir dir("gltf-lines-info");
  std::string path = dir.write("lines.gltf", b.gltf(one_primitive(prims))).string();
  CommandResult info = run_radiant("info " + path);
  CHECK(info.exit_code == 0);
  CHECK(info.out.find("2 line segments") != std::string::npos);
  CHECK(info.out.find("point") == std::string::npos);  // no count of a kind the file has none of
  CommandResult json = run_radiant("info --json " + path);
  CHECK(json.out.find("\"line_segments\": 2") != std::string::npos);
}

TEST_CASE("gltf: normalized and plain integer components of every type") {
  GltfBuilder b = quad_builder();
  // TEXCOORD_0 as normalized unsigned bytes, COLOR_0 as normalized unsigned shorts (VEC3).
  int uv = b.accessor(b.view(std::string("\x00\xff\xff\x00\xff\xff\x00\x00", 8)), 5121, 4, "VEC2", ",\"normalized\":true");
  std::vector<uint16_t> color = {65535, 0, 32768, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  int col = b.accessor(b.view(GltfBuilder::bytes_of(color)), 5123, 4, "VEC3", ",\"normalized\":true");
  // TEXCOORD_1 as normalized signed bytes: -128 clamps to -1.
  int uv1 = b.accessor(b.view(std::string("\x80\x7f\x00\x00\x00\x00\x00\x00", 8)), 5120, 4, "VEC2", ",\"normalized\":true");
  std::string prim = "{\"attributes\":{\"POSITION\":0,\"TEXCOORD_0\":" + std::to_string(uv) + ",\"COLOR_0\":" +
                     std::to_string(col) + ",\"TEXCOORD_1\":" + std::to_string(uv1) + "},\"indices\":1}";
  const MeshDesc mesh = load_text(b.gltf(one_primitive(prim))).meshes[0];
  CHECK(mesh.texcoords0[0].x == 0);
  CHECK(mesh.texcoords0[0].y == 1);
  CHECK(mesh.texcoords0[3].x == 0);
  CHECK(mesh.colors[0].x == 1);
  CHECK(mesh.colors[0].z == doctest::Approx(32768 / 65535.0));
  CHECK(mesh.colors[0].w == 1);  // VEC3 colors are opaque
  CHECK(mesh.texcoords1[0].x == -1);
  CHECK(mesh.texcoords1[0].y == 1);
}

TEST_CASE("gltf: signed short positions, byte indices and interleaved strides") {
  GltfBuilder b;
  // Interleaved: position (3 shorts) + 2 bytes padding + unused, stride 12.
  std::vector<int16_t> interleaved = {0, 0, 0, 7, 7, 7, 2, 0, 0, 7, 7, 7, 0, 2, 0, 7, 7, 7};
  int pos = b.accessor(b.view(GltfBuilder::bytes_of(interleaved), 12), 5122, 3, "VEC3");
  int idx = b.accessor(b.view(std::string("\x00\x01\x02", 3)), 5121, 3, "SCALAR");
  std::string prim = "{\"attributes\":{\"POSITION\":" + std::to_string(pos) + "},\"indices\":" + std::to_string(idx) + "}";
  const MeshDesc mesh = load_text(b.gltf(one_primitive(prim))).meshes[0];
  REQUIRE(mesh.positions.size() == 3);
  CHECK(mesh.positions[1].x == 2);
  CHECK(mesh.positions[2].y == 2);
  CHECK(mesh.positions[2].z == 0);
}

TEST_CASE("gltf: sparse accessors overwrite the listed elements") {
  GltfBuilder b = quad_builder();
  int indices = b.view(GltfBuilder::bytes_of(std::vector<uint16_t>{2, 0}));
  int values = b.view(GltfBuilder::bytes_of(std::vector<float>{5, 5, 5}));
  std::string sparse = ",\"sparse\":{\"count\":1,\"indices\":{\"bufferView\":" + std::to_string(indices) +
                       ",\"componentType\":5123},\"values\":{\"bufferView\":" + std::to_string(values) + "}}";
  // Based on the quad's positions; vertex 2 moves to (5,5,5).
  int pos = b.accessor(0, 5126, 4, "VEC3", sparse);
  std::string prim = "{\"attributes\":{\"POSITION\":" + std::to_string(pos) + "},\"indices\":1}";
  const MeshDesc mesh = load_text(b.gltf(one_primitive(prim))).meshes[0];
  CHECK(mesh.positions[2].x == 5);
  CHECK(mesh.positions[2].z == 5);
  CHECK(mesh.positions[1].x == 1);
}

TEST_CASE("gltf: degenerate triangles are dropped and counted") {
  GltfBuilder b;
  b.floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 2, 0, 0}, "VEC3", 3);
  b.indices({0, 1, 2, 0, 0, 1, 0, 1, 3});  // repeated index, then collinear
  SceneDesc scene = load_text(b.gltf(one_primitive("{\"attributes\":{\"POSITION\":0},\"indices\":1}")));
  CHECK(scene.meshes[0].indices == std::vector<uint32_t>{0, 1, 2});
  CHECK(scene.degenerate_triangles_dropped == 2);
  CHECK(scene.warnings.back() == scene.source_path + ": 2 degenerate triangles dropped");
}

TEST_CASE("gltf: zero-length normals are recomputed with a warning") {
  GltfBuilder b = quad_builder();
  int normals = b.floats({0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
  SceneDesc scene = load_text(b.gltf(one_primitive("{\"attributes\":{\"POSITION\":0,\"NORMAL\":" +
                                                   std::to_string(normals) + "},\"indices\":1}")));
  CHECK(scene.meshes[0].normals[1].z == doctest::Approx(1));
  CHECK(scene.warnings.at(0).find("attributes.NORMAL: 1 zero-length normals recomputed") != std::string::npos);
}

TEST_CASE("gltf: a GLB with the same content loads the same mesh") {
  GltfBuilder b = quad_builder();
  ScratchDir dir("gltf-glb");
  SceneDesc scene = load_scene(dir.write("quad.glb", b.glb(std::string(quad_mesh) +
                                                          ",\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]"))
                                   .string());
  CHECK(scene.meshes.at(0).positions.size() == 4);
  CHECK(scene.meshes.at(0).indices.size() == 6);
}

TEST_CASE("gltf: unsigned int indices and non-indexed triangle lists") {
  GltfBuilder b = quad_builder();
  int wide = b.accessor(b.view(GltfBuilder::bytes_of(std::vector<uint32_t>{3, 2, 0})), 5125, 3, "SCALAR");
  SceneDesc scene = load_text(b.gltf(one_primitive("{\"attributes\":{\"POSITION\":0},\"indices\":" +
                                                   std::to_string(wide) + "}")));
  CHECK(scene.meshes[0].indices == std::vector<uint32_t>{3, 2, 0});
  // Without indices, vertices are taken three at a time; a trailing incomplete triangle is ignored.
  GltfBuilder c;
  c.floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5}, "VEC3", 3);
  CHECK(load_text(c.gltf(one_primitive("{\"attributes\":{\"POSITION\":0}}"))).meshes[0].indices ==
        std::vector<uint32_t>{0, 1, 2});
}
