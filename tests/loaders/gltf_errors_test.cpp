// glTF errors: each names the file and the JSON path, in one line.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "loaders/gltf_builder.h"
#include "load_scene.h"
#include "support/load_errors.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

static const char* placed = ",\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]";

// The error message with the scratch folder removed, so tests compare whole lines.
static std::string error_of(const std::string& text, const std::string& name = "file.gltf",
                            const LoadOptions& options = {}) {
  ScratchDir dir("gltf-errors");
  return load_error(dir, dir.write(name, text), options);
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
  CHECK(error_of(b.gltf(body + ",\"extensionsUsed\":[\"KHR_gaussian_splatting\"],"
                               "\"extensionsRequired\":[\"KHR_gaussian_splatting\"]")) ==
        "file.gltf: extensionsRequired: unsupported extension KHR_gaussian_splatting");
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
        "file.gltf: scene: nothing to render (no meshes placed, no shapes, no lines or points)");
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

TEST_CASE("gltf errors: non-finite texture coordinates, tangents and vertex colors name the attribute") {
  // A NaN COLOR_0 must not reach the albedo AOV even where the color stays clean.
  float nan = std::nanf(""), inf = std::numeric_limits<float>::infinity();
  struct Case {
    const char* attribute;
    std::vector<float> values;
    const char* type;
    int components;
    const char* element;
  };
  for (const Case& c : {Case{"COLOR_0", {1, 1, 1, 1, 1, 1, nan, 1, 1, 1, 1, 1}, "VEC3", 3, "2"},
                        Case{"TEXCOORD_0", {0, 0, 1, 0, 1, inf, 0, 1}, "VEC2", 2, "2"},
                        Case{"TEXCOORD_1", {0, 0, 1, 0, 1, 1, 0, -inf}, "VEC2", 2, "3"},
                        Case{"TANGENT", {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, nan}, "VEC4", 4, "3"}}) {
    CAPTURE(c.attribute);
    GltfBuilder b = quad_builder();
    int bad = b.floats(c.values, c.type, c.components);
    std::string attributes = "{\"POSITION\":0,\"" + std::string(c.attribute) + "\":" + std::to_string(bad) + "}";
    CHECK(error_of(b.gltf("\"meshes\":[{\"primitives\":[{\"attributes\":" + attributes + ",\"indices\":1}]}]" +
                          placed)) == "file.gltf: meshes[0].primitives[0].attributes." + std::string(c.attribute) +
                                          ": non-finite value in element " + c.element);
  }
}

TEST_CASE("gltf errors: negative light intensity and color, emissive factor and strength name the place") {
  std::string lights_used = ",\"extensionsUsed\":[\"KHR_lights_punctual\",\"KHR_materials_emissive_strength\"]";
  auto with_light = [&](const std::string& light) {
    GltfBuilder b = quad_builder();
    return error_of(b.gltf(std::string(quad_mesh) +
                           ",\"nodes\":[{\"mesh\":0},{\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}}}],"
                           "\"scenes\":[{\"nodes\":[0,1]}],\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[" +
                           light + "]}}" + lights_used));
  };
  std::string lights = "file.gltf: extensions.KHR_lights_punctual.lights[0].";
  CHECK(with_light("{\"type\":\"point\",\"intensity\":-1}") == lights + "intensity: must not be negative, got -1");
  CHECK(with_light("{\"type\":\"point\",\"color\":[1,-0.5,1]}") == lights + "color: must not be negative, got -0.5");
  CHECK(with_light("{\"type\":\"point\",\"intensity\":1e39}") ==
        lights + "intensity: 1e+39 does not fit in a float");
  auto with_material = [&](const std::string& material) {
    GltfBuilder b = quad_builder();
    return error_of(b.gltf("\"materials\":[" + material +
                           "],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,"
                           "\"material\":0}]}]" + placed + lights_used));
  };
  CHECK(with_material("{\"emissiveFactor\":[1,1,-1]}") ==
        "file.gltf: materials[0].emissiveFactor: must not be negative, got -1");
  CHECK(with_material("{\"emissiveFactor\":[1,1,1],\"extensions\":{\"KHR_materials_emissive_strength\":"
                      "{\"emissiveStrength\":-2}}}") ==
        "file.gltf: materials[0].extensions.KHR_materials_emissive_strength.emissiveStrength: must not be "
        "negative, got -2");
}

TEST_CASE("gltf errors: indices and texCoords in extensions are checked before any conversion to int") {
  // Numbers that are not JSON integers are refused before tinygltf reads them (it would drop them).
  // `light: 1e10` was cast straight to int (undefined behaviour, caught by UBSan).
  auto with_light_index = [&](const std::string& index) {
    GltfBuilder b = quad_builder();
    return error_of(b.gltf(std::string(quad_mesh) + ",\"nodes\":[{\"mesh\":0,\"extensions\":{\"KHR_lights_punctual\":"
                                                    "{\"light\":" + index + "}}}],\"scenes\":[{\"nodes\":[0]}],"
                           "\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[{\"type\":\"point\"}]}},"
                           "\"extensionsUsed\":[\"KHR_lights_punctual\"]"));
  };
  std::string where = "file.gltf: nodes[0].extensions.KHR_lights_punctual.light: ";
  CHECK(with_light_index("1e10") == where + "1e10 is not an integer from 0 to 2147483647");
  CHECK(with_light_index("-1e300") == where + "-1e300 is not an integer from 0 to 2147483647");
  CHECK(with_light_index("0.5") == where + "0.5 is not an integer from 0 to 2147483647");
  CHECK(with_light_index("\"0\"") == where + "expected a light index, found a non-number");
  CHECK(with_light_index("0") == "no error");
  auto with_texture = [&](const std::string& material) {
    GltfBuilder b = quad_builder();
    b.floats({0, 0, 1, 0, 1, 1, 0, 1}, "VEC2", 2);
    return error_of(b.gltf("\"materials\":[" + material +
                           "],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"TEXCOORD_0\":2},"
                           "\"indices\":1,\"material\":0}]}]" + placed +
                           ",\"textures\":[{\"source\":0}],\"images\":[{\"uri\":\"data:image/png;base64,"
                           "iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mNkYPhfDwAChwGA60e6kgAAAABJRU5ErkJggg==\"}],"
                           "\"extensionsUsed\":[\"KHR_texture_transform\",\"KHR_materials_transmission\"]"));
  };
  CHECK(with_texture("{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0,\"extensions\":"
                     "{\"KHR_texture_transform\":{\"texCoord\":1e10}}}}}") ==
        "file.gltf: materials[0].pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform.texCoord: "
        "1e10 is not an integer from 0 to 2147483647");
  CHECK(with_texture("{\"extensions\":{\"KHR_materials_transmission\":{\"transmissionTexture\":{\"index\":1e10}}}}") ==
        "file.gltf: materials[0].extensions.KHR_materials_transmission.transmissionTexture.index: 1e10 is not an "
        "integer from 0 to 2147483647");
  CHECK(with_texture("{\"extensions\":{\"KHR_materials_transmission\":{\"transmissionTexture\":{\"index\":0,"
                     "\"texCoord\":-3e9}}}}") ==
        "file.gltf: materials[0].extensions.KHR_materials_transmission.transmissionTexture.texCoord: "
        "-3e9 is not an integer from 0 to 2147483647");
  CHECK(with_texture("{\"extensions\":{\"KHR_materials_specular\":{\"specularColorTexture\":{\"index\":7}}}}") ==
        "file.gltf: materials[0].extensions.KHR_materials_specular.specularColorTexture.index: texture 7 out "
        "of range (1 textures)");
}

TEST_CASE("gltf errors: KHR_materials_specular factors must be non-negative numbers") {
  auto with_specular = [](const std::string& specular) {
    GltfBuilder b = quad_builder();
    return error_of(b.gltf("\"materials\":[{\"extensions\":{\"KHR_materials_specular\":" + specular +
                           "}}],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,"
                           "\"material\":0}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]"));
  };
  std::string where = "file.gltf: materials[0].extensions.KHR_materials_specular.";
  CHECK(with_specular("{\"specularFactor\":-0.5}") == where + "specularFactor: must not be negative, got -0.5");
  CHECK(with_specular("{\"specularColorFactor\":[1,-1,1]}") == where + "specularColorFactor: must not be negative, got -1");
  CHECK(with_specular("{\"specularColorFactor\":[1,1]}") == where + "specularColorFactor: must be an array of 3 numbers");
  CHECK(with_specular("{\"specularColorFactor\":[1,\"a\",1]}") ==
        where + "specularColorFactor: must be an array of 3 numbers");
  CHECK(with_specular("{\"specularFactor\":0,\"specularColorFactor\":[1,1,1]}") == "no error");
}

TEST_CASE("gltf errors: clearcoat, sheen and volume factors must be non-negative numbers") {
  auto with_extension = [](const std::string& extensions) {
    GltfBuilder b = quad_builder();
    return error_of(b.gltf("\"materials\":[{\"extensions\":{" + extensions +
                           "}}],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,"
                           "\"material\":0}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]"));
  };
  std::string where = "file.gltf: materials[0].extensions.";
  CHECK(with_extension("\"KHR_materials_clearcoat\":{\"clearcoatFactor\":-1}") ==
        where + "KHR_materials_clearcoat.clearcoatFactor: must not be negative, got -1");
  CHECK(with_extension("\"KHR_materials_clearcoat\":{\"clearcoatRoughnessFactor\":1e39}") ==
        where + "KHR_materials_clearcoat.clearcoatRoughnessFactor: 1e+39 does not fit in a float");
  CHECK(with_extension("\"KHR_materials_sheen\":{\"sheenColorFactor\":[0,0,-2]}") ==
        where + "KHR_materials_sheen.sheenColorFactor: must not be negative, got -2");
  CHECK(with_extension("\"KHR_materials_sheen\":{\"sheenRoughnessFactor\":-0.1}") ==
        where + "KHR_materials_sheen.sheenRoughnessFactor: must not be negative, got -0.1");
  CHECK(with_extension("\"KHR_materials_volume\":{\"attenuationDistance\":0}") ==
        where + "KHR_materials_volume.attenuationDistance: must be positive, got 0");
  CHECK(with_extension("\"KHR_materials_volume\":{\"thicknessFactor\":-2}") ==
        where + "KHR_materials_volume.thicknessFactor: must not be negative, got -2");
  CHECK(with_extension("\"KHR_materials_dispersion\":{\"dispersion\":-0.5}") ==
        where + "KHR_materials_dispersion.dispersion: must not be negative, got -0.5");
  CHECK(with_extension("\"KHR_materials_volume\":{\"attenuationColor\":[1,1]}") ==
        where + "KHR_materials_volume.attenuationColor: must be an array of 3 numbers");
  CHECK(with_extension("\"KHR_materials_sheen\":{\"sheenColorFactor\":[1,1,1]},\"KHR_materials_clearcoat\":{},"
                       "\"KHR_materials_volume\":{\"thicknessFactor\":1,\"attenuationDistance\":3}") == "no error");
}

TEST_CASE("gltf errors: a NUL or line break in a URI is shown escaped, on one line") {
  std::string message = error_of("{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":4,"
                                 "\"uri\":\"a\\u0000b.bin\"}]}");
  CHECK(message == "file.gltf: buffers[0].uri: file name contains a NUL byte");
  message = error_of("{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":4,"
                     "\"uri\":\"/abs\\nolute.bin\"}]}");
  CHECK(message == "file.gltf: buffers[0].uri: '/abs\\nolute.bin' is an absolute path (use --allow-external-files "
                   "to allow it)");
}

TEST_CASE("gltf: a node scaled to zero is skipped with a warning naming the file and the node") {
  ScratchDir dir("gltf-scale-zero");
  GltfBuilder b = quad_builder();
  std::string path = dir.write("flat.gltf", b.gltf(std::string(quad_mesh) +
                                                   ",\"nodes\":[{\"mesh\":0},{\"mesh\":0,\"scale\":[1,0,1]}],"
                                                   "\"scenes\":[{\"nodes\":[0,1]}]"))
                         .string();
  SceneDesc scene = load_scene(path);
  CHECK(scene.instances.size() == 1);
  REQUIRE(scene.warnings.size() == 1);
  CHECK(scene.warnings[0] == path + ": nodes[1]: singular transform (a zero scale): the mesh is not rendered");
  CHECK(error_of(b.gltf(std::string(quad_mesh) + ",\"nodes\":[{\"mesh\":0,\"scale\":[0,0,0]}],"
                                                 "\"scenes\":[{\"nodes\":[0]}]")) ==
        "file.gltf: scene: nothing to render (no meshes placed, no shapes, no lines or points)");
}

TEST_CASE("gltf: a node scaled nearly to zero is skipped like a zero scale, not traced") {
  // Its float inverse is infinite: Embree aborted on the first ray that reached it.
  ScratchDir dir("gltf-scale-near-zero");
  GltfBuilder b = quad_builder();
  std::string path = dir.write("speck.gltf", b.gltf(std::string(quad_mesh) +
                                                    ",\"nodes\":[{\"mesh\":0},{\"mesh\":0,\"scale\":[1e-16,1e-16,1e-16]}],"
                                                    "\"scenes\":[{\"nodes\":[0,1]}]"))
                         .string();
  SceneDesc scene = load_scene(path);
  CHECK(scene.instances.size() == 1);
  REQUIRE(scene.warnings.size() == 1);
  CHECK(scene.warnings[0] ==
        path + ": nodes[1]: transform too close to singular to invert in single precision: the mesh is not rendered");
}

TEST_CASE("gltf errors: glTF 1.0 and GLB version 1 are refused as such") {
  CHECK(error_of("{\"asset\":{\"version\":\"1.0\"},\"meshes\":{}}") ==
        "file.gltf: asset.version: glTF 1.0 is not supported (radiant reads glTF 2.x)");
  CHECK(error_of("{\"asset\":{\"version\":\"3.0\"}}") ==
        "file.gltf: asset.version: glTF 3.0 is not supported (radiant reads glTF 2.x)");
  GltfBuilder b = quad_builder();
  std::string glb = b.glb(std::string(quad_mesh) + placed);
  CHECK(error_of(glb, "file.glb") == "no error");
  glb[4] = 1;  // the header's version field
  CHECK(error_of(glb, "file.glb") == "file.glb: GLB version 1 is not supported (radiant reads glTF 2.x)");
}

TEST_CASE("gltf errors: an index or byte offset that is not a non-negative JSON integer is refused, not dropped") {
  GltfBuilder b = quad_builder();
  std::string valid = b.gltf(std::string(quad_mesh) + ",\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]");
  // `valid` with its first `from` replaced by `to`.
  auto edited = [&](const std::string& from, const std::string& to) {
    std::string text = valid;
    size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    return error_of(text.replace(at, from.size(), to));
  };
  CHECK(edited("\"indices\":1", "\"indices\":1e30") ==
        "file.gltf: meshes[0].primitives[0].indices: 1e30 is not an integer from 0 to 2147483647");
  CHECK(edited("\"indices\":1", "\"indices\":0.5") ==
        "file.gltf: meshes[0].primitives[0].indices: 0.5 is not an integer from 0 to 2147483647");
  CHECK(edited("{\"mesh\":0}", "{\"mesh\":0,\"camera\":-1}") ==
        "file.gltf: nodes[0].camera: -1 is not an integer from 0 to 2147483647");
  CHECK(edited("{\"mesh\":0}", "{\"mesh\":0,\"camera\":4294967296}") ==
        "file.gltf: nodes[0].camera: 4294967296 is not an integer from 0 to 2147483647");
  CHECK(edited("\"byteOffset\":48", "\"byteOffset\":-4") ==
        "file.gltf: bufferViews[1].byteOffset: -4 is not an integer from 0 to 2^53");
  CHECK(edited("\"scenes\":", "\"scene\":-1,\"scenes\":") == "file.gltf: scene: -1 is not an integer from 0 to 2147483647");
  CHECK(edited("\"nodes\":[0]", "\"nodes\":[1.0]") == "file.gltf: scenes[0].nodes[0]: 1.0 is not an integer from 0 to 2147483647");
  CHECK(edited("\"POSITION\":0", "\"POSITION\":-0.0") ==
        "file.gltf: meshes[0].primitives[0].attributes.POSITION: -0.0 is not an integer from 0 to 2147483647");
  // A number quoted in the message is cut short.
  std::string long_number = "1" + std::string(500, '0');
  CHECK(edited("\"indices\":1", "\"indices\":" + long_number) == "file.gltf: meshes[0].primitives[0].indices: " +
                                                                   long_number.substr(0, 40) +
                                                                   "... is not an integer from 0 to 2147483647");
  // The application's own data in extras may hold any number.
  CHECK(edited("{\"mesh\":0}", "{\"mesh\":0,\"extras\":{\"camera\":-1.5,\"nodes\":[0.5]}}") == "no error");
  CHECK(edited("\"byteOffset\":48", "\"byteOffset\":48") == "no error");
}

TEST_CASE("gltf errors: tinygltf's messages without a place get one, and quote at most a few hundred bytes") {
  GltfBuilder b = quad_builder();
  std::string valid = b.gltf(std::string(quad_mesh) + placed);
  auto edited = [&](const std::string& from, const std::string& to) {
    std::string text = valid;
    size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
  };
  // nlohmann's "number overflow parsing '1e309'" named no place.
  CHECK(error_of(edited("\"type\":\"VEC3\"", "\"type\":\"VEC3\",\"max\":[1,1e309,0]")) ==
        "file.gltf: accessors[0].max[1]: 1e309 is beyond the range of a double");
  // "File size mismatch : PATH, requestedBytes 60, but got 50" named no buffer.
  ScratchDir dir("gltf-short-buffer");
  std::string data_uri = valid.substr(valid.find("data:application"));
  data_uri = data_uri.substr(0, data_uri.find('"'));
  dir.write("short.bin", std::string(50, '\0'));
  CHECK(load_error(dir, dir.write("file.gltf", edited(data_uri, "short.bin"))) ==
        "file.gltf: buffers[0].byteLength: 60 bytes, but 'short.bin' holds 50");
  // A data URI that does not decode was echoed whole (42 MB lines).
  std::string message = error_of(edited(data_uri, "data:application/octet-stream;base64," + std::string(1 << 20, '!')));
  CHECK(message.rfind("file.gltf: ", 0) == 0);
  CHECK(message.size() < 700);
}
