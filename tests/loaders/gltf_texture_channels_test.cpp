// Which texture channels, colour decoding, UV sets and KHR_texture_transform each glTF material
// slot reads, checked by resolving the loaded material where the two UV sets differ.
#include <doctest/doctest.h>

#include "load_scene.h"
#include "loaders/gltf_builder.h"
#include "materials/surface.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// A 2x1 RGBA PNG: left texel (255, 128, 0, alpha 51), right texel (0, 0, 255, alpha 255).
void write_two_texels(const std::filesystem::path& path) {
  write_texel_bytes(path, 2, 1, 4, {255, 128, 0, 51, 0, 0, 255, 255});
}
constexpr float srgb_128 = 0.21586f;  // the sRGB decoding of 128
constexpr float alpha_51 = 0.2f;      // 51 / 255, read as linear data

// The quad with two UV sets and a nearest-filtered texture over the PNG, and `materials`.
SceneDesc load_quad_with(ScratchDir& dir, const std::string& materials) {
  write_two_texels(dir.file("texels.png"));
  GltfBuilder b = quad_builder();
  b.floats({0, 0, 1, 0, 1, 1, 0, 1}, "VEC2", 2);
  b.floats({0, 0, 1, 0, 1, 1, 0, 1}, "VEC2", 2);
  std::string body =
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"TEXCOORD_0\":2,\"TEXCOORD_1\":3},"
      "\"indices\":1,\"material\":0}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],"
      "\"images\":[{\"uri\":\"texels.png\"}],\"samplers\":[{\"magFilter\":9728,\"minFilter\":9728}],"
      "\"textures\":[{\"source\":0,\"sampler\":0}],\"materials\":[" + materials + "]";
  return load_scene(dir.write("m.gltf", b.gltf(body)).string());
}

// A point whose first UV set reads the left texel and whose second reads the right one.
SurfaceAttributes left_in_set_0_right_in_set_1() {
  SurfaceAttributes a;
  a.uv[0] = {0.25f, 0.5f};
  a.uv[1] = {0.75f, 0.5f};
  return a;
}

}  // namespace

TEST_CASE("gltf textures: diffuse transmission reads its factor from alpha and its colour from sRGB RGB") {
  ScratchDir dir("gltf-diffuse-transmission");
  SceneDesc scene = load_quad_with(
      dir, "{\"extensions\":{\"KHR_materials_diffuse_transmission\":{\"diffuseTransmissionFactor\":0.5,"
           "\"diffuseTransmissionTexture\":{\"index\":0},\"diffuseTransmissionColorFactor\":[1,0.5,1],"
           "\"diffuseTransmissionColorTexture\":{\"index\":0,\"texCoord\":1}}}}");
  CHECK(scene.warnings.empty());
  const MaterialDesc& desc = scene.materials[0];
  CHECK(desc.diffuse_transmission == 0.5f);
  CHECK(desc.diffuse_transmission_color == color3{1, 0.5f, 1});
  CHECK(desc.diffuse_transmission_texture.texcoord == 0);
  CHECK(desc.diffuse_transmission_color_texture.texcoord == 1);
  SurfaceMaterial m = resolve_material(scene, desc, left_in_set_0_right_in_set_1());
  CHECK(m.diffuse_transmission == doctest::Approx(0.5 * alpha_51));  // the left texel's alpha
  CHECK(m.diffuse_transmission_color == color3{0, 0, 1});  // the right texel: blue
  SurfaceAttributes swapped;
  swapped.uv[0] = {0.75f, 0.5f};
  swapped.uv[1] = {0.25f, 0.5f};
  m = resolve_material(scene, desc, swapped);
  CHECK(m.diffuse_transmission == 0.5f);
  CHECK(m.diffuse_transmission_color.x == 1);
  CHECK(m.diffuse_transmission_color.y == doctest::Approx(0.5 * srgb_128).epsilon(1e-3));
  CHECK(m.diffuse_transmission_color.z == 0);
}

TEST_CASE("gltf textures: a bad diffuse transmission colour names its JSON path") {
  ScratchDir dir("gltf-diffuse-transmission-bad");
  CHECK_THROWS_WITH_AS(
      load_quad_with(dir, "{\"extensions\":{\"KHR_materials_diffuse_transmission\":{"
                          "\"diffuseTransmissionColorFactor\":[1,-2,1]}}}"),
      doctest::Contains("materials[0].extensions.KHR_materials_diffuse_transmission.diffuseTransmissionColorFactor"),
      LoadError);
}

// SheenCloth's case: both sheen textures are one RGBA image under KHR_texture_transform, which
// an extension's textureInfo carries in its own "extensions".
TEST_CASE("gltf textures: an extension's texture honours its KHR_texture_transform, texCoord override included") {
  ScratchDir dir("gltf-sheen-transform");
  SceneDesc scene = load_quad_with(
      dir, "{\"extensions\":{\"KHR_materials_sheen\":{\"sheenColorFactor\":[1,1,1],\"sheenRoughnessFactor\":1,"
           "\"sheenColorTexture\":{\"index\":0,\"extensions\":{\"KHR_texture_transform\":{\"offset\":[0.5,0]}}},"
           "\"sheenRoughnessTexture\":{\"index\":0,\"extensions\":{\"KHR_texture_transform\":{\"scale\":[3,-30],"
           "\"texCoord\":1}}}}}}");
  const MaterialDesc& desc = scene.materials[0];
  CHECK(desc.sheen_color_texture.offset.x == 0.5f);
  CHECK(desc.sheen_roughness_texture.scale.x == 3);
  CHECK(desc.sheen_roughness_texture.scale.y == -30);
  CHECK(desc.sheen_roughness_texture.texcoord == 1);
  SurfaceMaterial m = resolve_material(scene, desc, left_in_set_0_right_in_set_1());
  // Colour: set 0 at u 0.25, offset by 0.5 to the right texel (blue), RGB.
  CHECK(m.sheen_color == color3{0, 0, 1});
  // Roughness: set 1 at u 0.75 × 3 = 2.25, the left half of a repeat: the left texel's alpha.
  CHECK(m.sheen_roughness == doctest::Approx(alpha_51));
}

// MultiUVTest's case: the base colour on TEXCOORD_0, the emission on TEXCOORD_1.
TEST_CASE("gltf textures: each core texture reads its own UV set") {
  ScratchDir dir("gltf-multi-uv");
  SceneDesc scene = load_quad_with(dir, "{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}},"
                                        "\"emissiveFactor\":[1,1,1],\"emissiveTexture\":{\"index\":0,\"texCoord\":1}}");
  SurfaceMaterial m = resolve_material(scene, scene.materials[0], left_in_set_0_right_in_set_1());
  CHECK(m.base_color.x == 1);
  CHECK(m.base_color.y == doctest::Approx(srgb_128).epsilon(1e-3));
  CHECK(m.base_color.z == 0);
  CHECK(m.emission == color3{0, 0, 1});
}
