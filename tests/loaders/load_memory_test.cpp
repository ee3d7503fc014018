// The loaders charge what they are about to build against the memory limit, and refuse before
// building it: JSON trees, meshes from sparse accessors, OBJ and MTL contents, decoded images.
#include <doctest/doctest.h>

#include "load_scene.h"
#include "support/load_errors.h"
#include "support/hostile_files.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// The load's error with the scratch folder removed, or "no error".
std::string load_error(const ScratchDir& dir, const std::string& file, uint64_t max_memory_bytes) {
  LoadOptions options;
  options.max_memory_bytes = max_memory_bytes;
  return test::load_error(dir, dir.file(file), options);
}

bool starts_with(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }
bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

constexpr uint64_t MiB = uint64_t(1) << 20;

}  // namespace

TEST_CASE("load memory: a glTF's JSON values are counted and charged before tinygltf builds them") {
  ScratchDir dir("memory-json");
  dir.write("extras.gltf", gltf_with_extras(300000));  // 600 kB of text, about 60 MB as a JSON tree
  std::string message = load_error(dir, "extras.gltf", 16 * MiB);
  CHECK(starts_with(message, "extras.gltf: the JSON document (300"));
  CHECK(contains(message, " values): "));
  CHECK(contains(message, "over the memory limit of 16.0 MiB (--max-memory)"));
  CHECK(load_error(dir, "extras.gltf", 256 * MiB) == "no error");
}

TEST_CASE("load memory: every glTF material, node and primitive is charged at tinygltf's size") {
  ScratchDir dir("memory-json-elements");
  std::string empty_materials;
  for (int i = 0; i < 20000; ++i) empty_materials += i ? ",{}" : "{}";  // 60 kB; tinygltf: 2 KB each
  std::string text = gltf_with_extras(1);
  text.insert(text.size() - 1, ",\"materials\":[" + empty_materials + "]");
  dir.write("materials.gltf", text);
  std::string message = load_error(dir, "materials.gltf", 16 * MiB);
  CHECK(starts_with(message, "materials.gltf: the JSON document ("));
  CHECK(contains(message, "over the memory limit of 16.0 MiB"));
}

TEST_CASE("load memory: a sparse accessor without a bufferView is charged as the mesh it becomes") {
  ScratchDir dir("memory-sparse");
  dir.write("sparse.gltf", sparse_positions_gltf(2000000));  // 24 MB of floats, then the mesh
  std::string message = load_error(dir, "sparse.gltf", 32 * MiB);
  CHECK(starts_with(message, "sparse.gltf: meshes[0].primitives[0].attributes.POSITION: "));
  CHECK(contains(message, "needed (with "));
  CHECK(contains(message, "over the memory limit of 32.0 MiB (--max-memory)"));
}

TEST_CASE("load memory: MTL materials are counted before tinyobjloader parses them") {
  ScratchDir dir("memory-mtl");
  dir.write("many.mtl", mtl_with_materials(20000));  // 340 kB; tinyobjloader: about 2 KB each
  dir.write("many.obj", obj_using_mtl("many.mtl"));
  std::string message = load_error(dir, "many.obj", 8 * MiB);
  CHECK(starts_with(message, "many.obj: mtllib 'many.mtl': 20000 materials: "));
  CHECK(contains(message, "over the memory limit of 8.00 MiB (--max-memory)"));
  CHECK(load_error(dir, "many.obj", 256 * MiB) == "no error");
}

TEST_CASE("load memory: what tinyobjloader builds from an OBJ is charged from its counted lines") {
  ScratchDir dir("memory-obj");
  dir.write("faces.obj", obj_with_faces(200000));  // 1.6 MB; about 170 bytes a face once parsed
  std::string message = load_error(dir, "faces.obj", 16 * MiB);
  CHECK(starts_with(message, "faces.obj: 3 vertices, 200000 faces: "));
  CHECK(contains(message, "over the memory limit of 16.0 MiB (--max-memory)"));
  CHECK(load_error(dir, "faces.obj", 512 * MiB) == "no error");
}

TEST_CASE("load memory: the words of a .scene are charged as the tokens they become, before they are kept") {
  ScratchDir dir("memory-scene-words");
  dir.write("words.scene", scene_with_words(4, 400000));  // 3.2 MB of text, 77 MB of tokens
  std::string message = load_error(dir, "words.scene", 16 * MiB);
  CHECK(starts_with(message, "words.scene:2:1: the scene text: "));
  CHECK(contains(message, "over the memory limit of 16.0 MiB (--max-memory)"));
}

TEST_CASE("load memory: a glTF image is charged by the size its header declares, before decoding") {
  ScratchDir dir("memory-gltf-image");
  dir.write("big.jpg", truncated_jpeg(dir.path, 8000, 8000));
  dir.write("big.gltf", gltf_textured_triangle("big.jpg"));
  // 8000 x 8000 fits in 256 MiB once, not as the copies decoding makes.
  std::string message = load_error(dir, "big.gltf", 256 * MiB);
  CHECK(starts_with(message, "big.gltf: images[0]: a 8000x8000 image: "));
  CHECK(contains(message, "over the memory limit of 256 MiB (--max-memory)"));
}

TEST_CASE("load memory: a truncated JPEG is refused, not decoded into zero-filled texels") {
  ScratchDir dir("memory-truncated");
  dir.write("cut.jpg", truncated_jpeg(dir.path, 64, 64));
  dir.write("cut.gltf", gltf_textured_triangle("cut.jpg"));
  CHECK(load_error(dir, "cut.gltf", 0) ==
        "cut.gltf: images[0]: the JPEG data is truncated (no end-of-image marker after its scan)");
  std::string mtl;
  dir.write("cut.obj", obj_textured_triangle("cut.mtl", "cut.jpg", mtl));
  dir.write("cut.mtl", mtl);
  std::string message = load_error(dir, "cut.obj", 0);
  CHECK(starts_with(message, "cut.obj: material 't' map_Kd: cannot decode image 'cut.jpg': "));
  CHECK(contains(message, "Premature end of JPEG file"));
}

TEST_CASE("load memory: an OBJ texture is charged by the size its header declares, before decoding") {
  ScratchDir dir("memory-obj-image");
  dir.write("big.jpg", truncated_jpeg(dir.path, 8000, 8000));
  std::string mtl;
  dir.write("big.obj", obj_textured_triangle("big.mtl", "big.jpg", mtl));
  dir.write("big.mtl", mtl);
  std::string message = load_error(dir, "big.obj", 64 * MiB);
  CHECK(starts_with(message, "big.obj: material 't' map_Kd: image 'big.jpg': "));
  CHECK(contains(message, "big.jpg: decoding its 8000x8000 pixels: 244 MiB needed"));
  CHECK(contains(message, "over the memory limit of 64.0 MiB (--max-memory)"));
}
