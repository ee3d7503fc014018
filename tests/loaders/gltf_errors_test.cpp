// glTF errors: each names the file and the JSON path, in one line.
#include <doctest/doctest.h>

#include "loaders/gltf_builder.h"
#include "load_scene.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

static const char* placed = ",\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]";

// The error message with the scratch folder removed, so tests compare whole lines.
static std::string error_of(const std::string& text, const std::string& name = "file.gltf",
                            const LoadOptions& options = {}) {
  ScratchDir dir("gltf-errors");
  std::string path = dir.write(name, text).string();
  try {
    load_scene(path, options);
  } catch (const LoadError& error) {
    std::string message = error.what();
    std::string folder = dir.path.string() + "/";
    for (size_t at; (at = message.find(folder)) != std::string::npos;) message.erase(at, folder.size());
    return message;
  }
  return "no error";
}

static std::string primitive_doc(GltfBuilder& b, const std::string& primitive) {
  return b.gltf("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}," + primitive + "]}]" +
                placed);
}

TEST_CASE("gltf errors: an index past the vertex count") {
  GltfBuilder b = quad_builder();
  int bad = b.indices({0, 1, 4100});
  CHECK(error_of(primitive_doc(b, "{\"attributes\":{\"POSITION\":0},\"indices\":" + std::to_string(bad) + "}")) ==
        "file.gltf: meshes[0].primitives[1].indices: index 4100 out of range (4 vertices)");
}

TEST_CASE("gltf errors: accessors past the end of their bufferView, and views past their buffer") {
  GltfBuilder b = quad_builder();
  int past = b.accessor(0, 5126, 5, "VEC3");  // 5 positions in a 4-position view
  CHECK(error_of(primitive_doc(b, "{\"attributes\":{\"POSITION\":" + std::to_string(past) + "}}")) ==
        "file.gltf: meshes[0].primitives[1].attributes.POSITION: accessor runs past the end of bufferViews[0] (48 bytes)");
  GltfBuilder c = quad_builder();
  c.views[0] = "{\"buffer\":0,\"byteOffset\":40,\"byteLength\":48}";
  CHECK(error_of(primitive_doc(c, "{\"attributes\":{\"POSITION\":0}}")) ==
        "file.gltf: meshes[0].primitives[0].attributes.POSITION: bufferViews[0] runs past the end of buffers[0] (60 bytes)");
}

TEST_CASE("gltf errors: wrong accessor types and component types") {
  GltfBuilder b = quad_builder();
  CHECK(error_of(primitive_doc(b, "{\"attributes\":{\"POSITION\":1}}")) ==
        "file.gltf: meshes[0].primitives[1].attributes.POSITION: expected VEC3, found SCALAR");
  CHECK(error_of(primitive_doc(b, "{\"attributes\":{\"POSITION\":0},\"indices\":0}")) ==
        "file.gltf: meshes[0].primitives[1].indices: expected SCALAR, found VEC3");
  CHECK(error_of(primitive_doc(b, "{\"attributes\":{\"POSITION\":0,\"NORMAL\":9}}")) ==
        "file.gltf: meshes[0].primitives[1].attributes.NORMAL: accessor 9 out of range (2 accessors)");
  CHECK(error_of(primitive_doc(b, "{\"attributes\":{\"NORMAL\":0}}")) ==
        "file.gltf: meshes[0].primitives[1].attributes: no POSITION attribute");
  int floats = b.floats({0, 1, 2}, "SCALAR", 1);
  CHECK(error_of(primitive_doc(b, "{\"attributes\":{\"POSITION\":0},\"indices\":" + std::to_string(floats) + "}")) ==
        "file.gltf: meshes[0].primitives[1].indices: indices must be unsigned integers, found FLOAT");
}

TEST_CASE("gltf errors: attribute counts must match POSITION") {
  GltfBuilder b = quad_builder();
  int normals = b.floats({0, 0, 1, 0, 0, 1}, "VEC3", 3);
  CHECK(error_of(primitive_doc(b, "{\"attributes\":{\"POSITION\":0,\"NORMAL\":" + std::to_string(normals) + "}}")) ==
        "file.gltf: meshes[0].primitives[1].attributes.NORMAL: 2 elements, but POSITION has 4");
}

TEST_CASE("gltf errors: non-finite positions and normals") {
  GltfBuilder b;
  float inf = std::numeric_limits<float>::infinity();
  b.floats({0, 0, 0, 1, 0, 0, inf, 1, 0}, "VEC3", 3);
  b.floats({0, 0, 1, 0, 0, 1, 0, std::nanf(""), 1}, "VEC3", 3);
  std::string meshes = "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}]";
  CHECK(error_of(b.gltf(meshes + placed)) ==
        "file.gltf: meshes[0].primitives[0].attributes.POSITION: non-finite value in element 2");
  GltfBuilder c = quad_builder();
  c.floats({0, 0, 1, 0, 0, 1, 0, std::nanf(""), 1, 0, 0, 1}, "VEC3", 3);
  CHECK(error_of(c.gltf("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":2}}]}]" +
                        std::string(placed))) ==
        "file.gltf: meshes[0].primitives[0].attributes.NORMAL: non-finite value in element 2");
}

TEST_CASE("gltf errors: a required extension radiant lacks is named, optional ones warn") {
  GltfBuilder b = quad_builder();
  std::string body = std::string(quad_mesh) + placed;
  CHECK(error_of(b.gltf(body + ",\"extensionsUsed\":[\"KHR_draco_mesh_compression\"],"
                               "\"extensionsRequired\":[\"KHR_draco_mesh_compression\"]")) ==
        "file.gltf: extensionsRequired: unsupported extension KHR_draco_mesh_compression");
  ScratchDir dir("gltf-optional");
  std::string path = dir.write("o.gltf", b.gltf(body + ",\"extensionsUsed\":[\"EXT_fancy\"]")).string();
  SceneDesc scene = load_scene(path);
  CHECK(scene.warnings.at(0) == path + ": extension EXT_fancy is not supported and is ignored");
}

TEST_CASE("gltf errors: files declaring more memory than allowed are refused before loading") {
  std::string text = "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":16,\"uri\":\"a.bin\"},"
                     "{\"byteLength\":1000000000000,\"uri\":\"huge.bin\"}]}";
  std::string message = error_of(text);
  CHECK(message.rfind("file.gltf: buffers[1].byteLength: 931 GiB needed (with ", 0) == 0);
  CHECK(message.find("over the memory limit of " + format_bytes(default_memory_limit()) +
                     " (a quarter of RAM; raise it with --max-memory)") != std::string::npos);
  LoadOptions small;
  small.max_memory_bytes = 60000;
  GltfBuilder b = quad_builder();  // a 60-byte buffer in a 544-byte file
  CHECK(error_of(b.gltf(std::string(quad_mesh) + placed), "file.gltf", small) == "no error");
  b.bin += std::string(60000, '\0');  // declared in a missing external file: refused before reading it
  message = error_of(b.gltf(std::string(quad_mesh) + placed, "missing.bin"), "file.gltf", small);
  CHECK(message.rfind("file.gltf: buffers[0].byteLength: 58.7 KiB needed (with ", 0) == 0);
  CHECK(message.find("over the memory limit of 58.6 KiB (--max-memory)") != std::string::npos);
}

TEST_CASE("gltf errors: tinygltf's own complaints become one line with the file name") {
  std::string message = error_of("{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":4}]}");
  CHECK(message.rfind("file.gltf: ", 0) == 0);
  CHECK(message.find('\n') == std::string::npos);
  CHECK(error_of("{\"asset\":") == "file.gltf: invalid JSON at byte 9: unexpected end");
  CHECK(error_of("not a glb at all", "file.glb").rfind("file.glb: ", 0) == 0);
}

TEST_CASE("gltf errors: a file with nothing placed has nothing to render") {
  CHECK(error_of(quad_builder().gltf(std::string(quad_mesh) + ",\"scenes\":[{\"nodes\":[]}]")) ==
        "file.gltf: scene: nothing to render (no meshes placed and no shapes)");
}

TEST_CASE("gltf errors: reading one accessor from many primitives is charged every time") {
  GltfBuilder b = quad_builder();
  std::string primitives;
  for (int i = 0; i < 40; ++i) primitives += std::string(i ? "," : "") + "{\"attributes\":{\"POSITION\":0},\"indices\":1}";
  std::string text = b.gltf("\"meshes\":[{\"primitives\":[" + primitives + "]}]" + placed);
  // The smallest limit the file loads under: one byte less, and the last primitive's reads are
  // the ones refused, after the 39 before it were charged.
  LoadOptions options;
  uint64_t fails = 0, loads = uint64_t(1) << 30;
  while (loads - fails > 1) {
    options.max_memory_bytes = (fails + loads) / 2;
    (error_of(text, "file.gltf", options) == "no error" ? loads : fails) = options.max_memory_bytes;
  }
  options.max_memory_bytes = fails;
  std::string message = error_of(text, "file.gltf", options);
  CHECK(message.rfind("file.gltf: meshes[0].primitives[39]", 0) == 0);
  CHECK(message.find("over the memory limit of") != std::string::npos);
}
