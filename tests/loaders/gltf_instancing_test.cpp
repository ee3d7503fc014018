// EXT_mesh_gpu_instancing: one instance per accessor element at node × T·R·S, every attribute
// optional, quantized rotations, mirrored and hidden instances, animation, and the errors that
// name the extension's JSON path.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "load_scene.h"
#include "loaders/gltf_builder.h"
#include "scene/scene_summary.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// The unit quad (accessors 0, 1) and node 0 placing it with `extension` and `node_extra` members.
std::string instanced_quad(GltfBuilder& b, const std::string& extension, const std::string& node_extra = "",
                           const std::string& more = "") {
  return b.gltf(std::string(quad_mesh) + ",\"extensionsUsed\":[\"EXT_mesh_gpu_instancing\"]," +
                "\"nodes\":[{\"mesh\":0" + node_extra + ",\"extensions\":{\"EXT_mesh_gpu_instancing\":" + extension +
                "}}],\"scenes\":[{\"nodes\":[0]}]" + more);
}

SceneDesc load_text(const std::string& gltf, const LoadOptions& options = {}) {
  ScratchDir dir("gltf-instancing");
  return load_scene(dir.write("scene.gltf", gltf).string(), options);
}

std::string load_error(const std::string& gltf, const LoadOptions& options = {}) {
  try {
    load_text(gltf, options);
  } catch (const LoadError& error) {
    std::string message = error.what();
    return message.substr(message.find("scene.gltf: ") + 12);
  }
  return "no error";
}

vec3 world_of(const SceneDesc& scene, size_t instance, vec3 p) {
  return transform_point(scene.instances.at(instance).transform, p);
}

}  // namespace

TEST_CASE("gltf instancing: each element places the mesh at the node's transform times its T*R*S") {
  GltfBuilder b = quad_builder();
  int t = b.floats({0, 0, 0, 5, 0, 0, 0, 7, 0}, "VEC3", 3);
  int r = b.floats({0, 0, 0, 1, 0, 0, 0.70710678f, 0.70710678f, 0, 0, 0, 1}, "VEC4", 4);
  int s = b.floats({1, 1, 1, 2, 2, 2, 1, 1, 3}, "VEC3", 3);
  std::string extension = "{\"attributes\":{\"TRANSLATION\":" + std::to_string(t) + ",\"ROTATION\":" +
                          std::to_string(r) + ",\"SCALE\":" + std::to_string(s) + "}}";
  SceneDesc scene = load_text(instanced_quad(b, extension, ",\"translation\":[0,0,10]"));
  REQUIRE(scene.instances.size() == 3);
  CHECK(scene.meshes.size() == 1);  // the mesh is stored once
  CHECK(world_of(scene, 0, {1, 1, 0}) == vec3{1, 1, 10});
  // Instance 1: scale 2, a quarter turn about z, then +5 in x, then the node's +10 in z.
  vec3 p = world_of(scene, 1, {1, 0, 0});
  CHECK(p.x == doctest::Approx(5));
  CHECK(p.y == doctest::Approx(2));
  CHECK(p.z == doctest::Approx(10));
  CHECK(world_of(scene, 2, {0, 0, 1}) == vec3{0, 7, 13});
  CHECK(summarize_scene(scene).instances == 3);
  CHECK(scene.warnings.empty());
}

TEST_CASE("gltf instancing: absent attributes are identity, and ROTATION may be normalized BYTE or SHORT") {
  GltfBuilder b = quad_builder();
  int s = b.floats({2, 2, 2, 3, 3, 3}, "VEC3", 3);
  // A quarter turn about z as normalized bytes: (0, 0, 90, 90) / 127.
  std::vector<int8_t> quarter = {0, 0, 90, 90, 0, 0, 0, 127};
  int r = b.accessor(b.view(GltfBuilder::bytes_of(quarter)), 5120, 2, "VEC4", ",\"normalized\":true");
  SceneDesc scaled = load_text(instanced_quad(b, "{\"attributes\":{\"SCALE\":" + std::to_string(s) + "}}"));
  REQUIRE(scaled.instances.size() == 2);
  CHECK(world_of(scaled, 1, {1, 1, 0}) == vec3{3, 3, 0});
  SceneDesc turned = load_text(instanced_quad(b, "{\"attributes\":{\"ROTATION\":" + std::to_string(r) + "}}"));
  REQUIRE(turned.instances.size() == 2);
  vec3 p = world_of(turned, 0, {1, 0, 0});  // normalized after dequantizing: an exact quarter turn
  CHECK(p.x == doctest::Approx(0).epsilon(1e-6));
  CHECK(p.y == doctest::Approx(1));
  CHECK(world_of(turned, 1, {1, 0, 0}) == vec3{1, 0, 0});
}

TEST_CASE("gltf instancing: a mirroring instance takes the mirrored mesh, a zero scale hides one") {
  GltfBuilder b = quad_builder();
  int s = b.floats({1, 1, 1, 1, 1, -1, 0, 0, 0}, "VEC3", 3);
  SceneDesc scene = load_text(instanced_quad(b, "{\"attributes\":{\"SCALE\":" + std::to_string(s) + "}}"));
  REQUIRE(scene.instances.size() == 2);
  CHECK(scene.instances[0].mesh != scene.instances[1].mesh);
  CHECK(scene.meshes[size_t(scene.instances[1].mesh)].name.find("(mirrored)") != std::string::npos);
  REQUIRE(scene.warnings.size() == 1);
  CHECK(scene.warnings[0].find("nodes[0].extensions.EXT_mesh_gpu_instancing: 1 of 3 instances have a singular "
                               "transform") != std::string::npos);
}

TEST_CASE("gltf instancing: an animated node moves all its instances") {
  GltfBuilder b = quad_builder();
  int t = b.floats({0, 0, 0, 5, 0, 0}, "VEC3", 3);
  int times = b.floats({0, 1}, "SCALAR", 1);
  int values = b.floats({0, 0, 0, 0, 2, 0}, "VEC3", 3);
  std::string gltf = instanced_quad(
      b, "{\"attributes\":{\"TRANSLATION\":" + std::to_string(t) + "}}", "",
      ",\"animations\":[{\"channels\":[{\"sampler\":0,\"target\":{\"node\":0,\"path\":\"translation\"}}],"
      "\"samplers\":[{\"input\":" + std::to_string(times) + ",\"output\":" + std::to_string(values) + "}]}]");
  LoadOptions options;
  options.animation_time = 0.5;
  SceneDesc scene = load_text(gltf, options);
  REQUIRE(scene.instances.size() == 2);
  CHECK(world_of(scene, 0, {0, 0, 0}) == vec3{0, 1, 0});
  CHECK(world_of(scene, 1, {0, 0, 0}) == vec3{5, 1, 0});
}

TEST_CASE("gltf instancing: bad attributes are errors naming the extension's JSON path") {
  GltfBuilder b = quad_builder();
  int two = b.floats({0, 0, 0, 1, 0, 0}, "VEC3", 3);
  int three = b.floats({1, 1, 1, 1, 1, 1, 1, 1, 1}, "VEC3", 3);
  int vec2 = b.floats({0, 0, 1, 1}, "VEC2", 2);
  int zero_rotation = b.floats({0, 0, 0, 0}, "VEC4", 4);
  float inf = std::numeric_limits<float>::infinity();
  int infinite = b.floats({0, inf, 0}, "VEC3", 3);
  std::vector<uint32_t> ints = {0, 0, 0};
  int unsigned_int = b.accessor(b.view(GltfBuilder::bytes_of(ints)), 5125, 1, "VEC3");
  std::vector<int8_t> bytes = {0, 0, 0, 127};
  int raw_bytes = b.accessor(b.view(GltfBuilder::bytes_of(bytes)), 5120, 1, "VEC4");  // not normalized
  auto error = [&](const std::string& attributes) { return load_error(instanced_quad(b, "{\"attributes\":{" + attributes + "}}")); };
  const std::string path = "nodes[0].extensions.EXT_mesh_gpu_instancing";
  CHECK(error("\"TRANSLATION\":" + std::to_string(two) + ",\"SCALE\":" + std::to_string(three)) ==
        path + ".attributes.SCALE: 3 elements, but the other attributes have 2 (all must have the same count)");
  CHECK(error("\"TRANSLATION\":" + std::to_string(vec2)) == path + ".attributes.TRANSLATION: expected VEC3, found VEC2");
  CHECK(error("\"SCALE\":" + std::to_string(infinite)) == path + ".attributes.SCALE: non-finite value in element 0");
  CHECK(error("\"ROTATION\":" + std::to_string(zero_rotation)) ==
        path + ".attributes.ROTATION: element 0 is not a rotation quaternion");
  CHECK(error("\"TRANSLATION\":" + std::to_string(unsigned_int)) ==
        path + ".attributes.TRANSLATION: must be FLOAT, BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT");
  CHECK(error("\"ROTATION\":" + std::to_string(raw_bytes)) ==
        path + ".attributes.ROTATION: must be FLOAT, or normalized BYTE or SHORT");
  CHECK(error("\"TRANSLATION\":99") == path + ".attributes.TRANSLATION: accessor 99 out of range (" +
                                           std::to_string(b.accessors.size()) + " accessors)");
  CHECK(error("\"TRANSLATION\":0.5") == path + ".attributes.TRANSLATION: 0.5 is not an integer from 0 to 2147483647");
  CHECK(error("\"_ID\":0") == path + ".attributes: names none of TRANSLATION, ROTATION and SCALE");
  CHECK(load_error(instanced_quad(b, "{}")) ==
        path + ".attributes: missing (an object naming TRANSLATION, ROTATION or SCALE accessors)");
}

TEST_CASE("gltf instancing: the instances are charged to the memory budget before they are made") {
  // Two million instances, all at the origin (a sparse accessor without a bufferView is zeros):
  // 24 MB of translations fit a 64 MiB budget, the instances do not.
  GltfBuilder b = quad_builder();
  int t = b.accessor(-1, 5126, 2000000, "VEC3");
  LoadOptions options;
  options.max_memory_bytes = 64ull << 20;
  std::string message = load_error(instanced_quad(b, "{\"attributes\":{\"TRANSLATION\":" + std::to_string(t) + "}}"), options);
  CAPTURE(message);
  CHECK(message.rfind("nodes[0].extensions.EXT_mesh_gpu_instancing: ", 0) == 0);
  CHECK(message.find("over the memory limit") != std::string::npos);
}
