// Texture image extensions: EXT_texture_webp read through OpenImageIO, PNG/JPEG fallbacks for
// the image formats radiant lacks (KHR_texture_basisu), and a clear error without one.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>

#include "load_scene.h"
#include "loaders/gltf_builder.h"
#include "support/load_errors.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// A textured triangle whose texture 0 is `texture` (JSON) over the images `images` (JSON).
std::string textured_triangle(const std::string& images, const std::string& texture, const std::string& extensions) {
  GltfBuilder b;
  b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
  b.floats({0, 0, 1, 0, 0, 1}, "VEC2", 2);
  return b.gltf(extensions + "\"images\":[" + images + "],\"textures\":[" + texture + "]," +
                "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}}}],"
                "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"TEXCOORD_0\":1},\"material\":0}]}],"
                "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],\"scene\":0");
}

// A file with the KTX2 signature: radiant recognises it and never decodes it.
const std::string ktx2_bytes = std::string("\xABKTX 20\xBB\r\n\x1A\n", 12) + std::string(64, '\0');

bool has_warning_containing(const SceneDesc& scene, const std::string& text) {
  return std::any_of(scene.warnings.begin(), scene.warnings.end(),
                     [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

}  // namespace

TEST_CASE("gltf textures: EXT_texture_webp is read through OpenImageIO, its PNG fallback left unused") {
  ScratchDir dir("gltf-webp");
  write_texel_bytes(dir.file("red.png"), 2, 2, 3, {255, 0, 0, 255, 0, 0, 255, 0, 0, 255, 0, 0});
  write_test_image(dir.file("blue.webp"), 2, 2, {"R", "G", "B"}, {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
  std::string path =
      dir.write("webp.gltf", textured_triangle("{\"uri\":\"red.png\"},{\"uri\":\"blue.webp\"}",
                                               "{\"source\":0,\"extensions\":{\"EXT_texture_webp\":{\"source\":1}}}",
                                               "\"extensionsUsed\":[\"EXT_texture_webp\"],"))
          .string();
  SceneDesc scene = load_scene(path);
  REQUIRE(scene.images.size() == 1);
  const ImageDesc& image = scene.images[0];
  CHECK(image.width == 2);
  REQUIRE(image.channels >= 3);
  REQUIRE(image.texels8.size() >= 3);
  CHECK(image.texels8[0] <= 4);    // lossy WebP keeps a flat color within a few steps
  CHECK(image.texels8[2] >= 251);
  CHECK_FALSE(has_warning_containing(scene, "EXT_texture_webp"));
  // Inside the file (a bufferView), a WebP image is refused by name.
  GltfBuilder b;
  b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
  int view = b.view(read_bytes(dir.file("blue.webp")));
  std::string embedded = b.gltf(
      "\"images\":[{\"bufferView\":" + std::to_string(view) + ",\"mimeType\":\"image/webp\"}],"
      "\"textures\":[{\"extensions\":{\"EXT_texture_webp\":{\"source\":0}}}],"
      "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}}}],"
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"material\":0}]}],"
      "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],\"scene\":0");
  CHECK(load_error(dir, dir.write("embedded.gltf", embedded)) ==
        "embedded.gltf: images[0]: a WebP image inside the file (bufferView or data URI) is not supported; a .webp "
        "file beside it is");
}

TEST_CASE("gltf textures: KHR_texture_basisu uses the PNG fallback source quietly, and without one says where") {
  ScratchDir dir("gltf-basisu");
  write_texel_bytes(dir.file("red.png"), 1, 1, 3, {255, 0, 0});
  dir.write("red.ktx2", ktx2_bytes);
  const std::string images = "{\"uri\":\"red.png\"},{\"uri\":\"red.ktx2\"}";
  const std::string with_fallback = "{\"source\":0,\"extensions\":{\"KHR_texture_basisu\":{\"source\":1}}}";
  std::string path = dir.write("fallback.gltf", textured_triangle(images, with_fallback,
                                                                  "\"extensionsUsed\":[\"KHR_texture_basisu\"],"))
                         .string();
  SceneDesc scene = load_scene(path);
  REQUIRE(scene.images.size() == 1);
  CHECK(scene.images[0].texels8 == std::vector<uint8_t>{255, 0, 0});
  CHECK(scene.warnings.empty());
  // Listed as required (the specification asks for that only without fallbacks), the fallback still serves.
  SceneDesc required = load_scene(
      dir.write("required.gltf",
                textured_triangle(images, with_fallback,
                                  "\"extensionsUsed\":[\"KHR_texture_basisu\"],\"extensionsRequired\":[\"KHR_texture_basisu\"],"))
          .string());
  CHECK(required.images.at(0).texels8 == std::vector<uint8_t>{255, 0, 0});
  CHECK(required.warnings.empty());
  dir.write("none.gltf", textured_triangle("{\"uri\":\"red.ktx2\"}",
                                           "{\"extensions\":{\"KHR_texture_basisu\":{\"source\":0}}}",
                                           "\"extensionsUsed\":[\"KHR_texture_basisu\"],\"extensionsRequired\":[\"KHR_texture_basisu\"],"));
  CHECK(load_error(dir, dir.file("none.gltf")) ==
        "none.gltf: textures[0].extensions.KHR_texture_basisu.source: KHR_texture_basisu images are not supported "
        "and the texture has no PNG or JPEG fallback source");
  dir.write("direct.gltf", textured_triangle("{\"uri\":\"red.ktx2\"}", "{\"source\":0}", ""));
  CHECK(load_error(dir, dir.file("direct.gltf")) ==
        "direct.gltf: images[0]: KTX2 images (KHR_texture_basisu) are not supported");
}
