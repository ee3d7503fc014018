// KHR_materials_pbrSpecularGlossiness converted to metallic-roughness with KHR_materials_specular.
#include <doctest/doctest.h>

#include <algorithm>

#include "loaders/gltf_builder.h"
#include "load_scene.h"
#include "materials/metallic_roughness.h"
#include "support/load_errors.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// A quad whose primitive uses material 0, with texcoords, and `more` top-level members.
std::string spec_gloss_file(const std::string& materials, const std::string& more = "") {
  GltfBuilder b = quad_builder();
  b.floats({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2", 2);
  return b.gltf("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"TEXCOORD_0\":2},\"indices\":1,"
                "\"material\":0}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],"
                "\"extensionsUsed\":[\"KHR_materials_pbrSpecularGlossiness\"],"
                "\"extensionsRequired\":[\"KHR_materials_pbrSpecularGlossiness\"],\"materials\":[" +
                materials + "]" + more);
}

size_t warnings_containing(const SceneDesc& scene, const std::string& text) {
  return size_t(std::count_if(scene.warnings.begin(), scene.warnings.end(),
                              [&](const std::string& w) { return w.find(text) != std::string::npos; }));
}

}  // namespace

TEST_CASE("gltf spec-gloss: factors become base colour, the coating's F0 and 1 - glossiness, over pbrMetallicRoughness") {
  ScratchDir dir("gltf-spec-gloss");
  std::string material =
      "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0,1,0,1],\"metallicFactor\":1,\"roughnessFactor\":0.1},"
      "\"extensions\":{\"KHR_materials_pbrSpecularGlossiness\":{\"diffuseFactor\":[0.5,0.25,1,0.75],"
      "\"specularFactor\":[0.02,0.04,0.5],\"glossinessFactor\":0.7}}}";
  SceneDesc scene = load_scene(dir.write("sg.gltf", spec_gloss_file(material + "," + material)).string());
  const MaterialDesc& m = scene.materials.at(0);
  CHECK(m.base_color == color3{0.5f, 0.25f, 1});
  CHECK(m.alpha == 0.75f);
  CHECK(m.metallic == 0);
  CHECK(m.roughness == doctest::Approx(0.3f));
  CHECK(m.specular == 1);
  color3 f0 = tinted_dielectric_f0(m.ior, m.specular_color);  // what the BSDF reflects at normal incidence
  CHECK(f0.x == doctest::Approx(0.02f));
  CHECK(f0.y == doctest::Approx(0.04f));
  CHECK(f0.z == doctest::Approx(0.5f));
  CHECK(warnings_containing(scene, "sg.gltf: materials[0].extensions.KHR_materials_pbrSpecularGlossiness: 2 "
                                   "specular-glossiness material(s) converted to metallic-roughness") == 1);
  CHECK(scene.warnings.size() == 1);
  // The extension's defaults: white diffuse, full specular, glossy.
  SceneDesc defaults =
      load_scene(dir.write("d.gltf", spec_gloss_file("{\"extensions\":{\"KHR_materials_pbrSpecularGlossiness\":{}}}"))
                     .string());
  CHECK(defaults.materials.at(0).base_color == color3{1, 1, 1});
  CHECK(defaults.materials.at(0).roughness == 0);
  CHECK(tinted_dielectric_f0(1.5f, defaults.materials.at(0).specular_color).x == doctest::Approx(1));
  dir.write("bad.gltf", spec_gloss_file("{\"extensions\":{\"KHR_materials_pbrSpecularGlossiness\":{\"glossinessFactor\":2}}}"));
  CHECK(load_error(dir, dir.file("bad.gltf")) ==
        "bad.gltf: materials[0].extensions.KHR_materials_pbrSpecularGlossiness.glossinessFactor: must be between 0 and "
        "1, got 2");
}

TEST_CASE("gltf spec-gloss: the textures' RGB is the specular colour and their alpha the glossiness") {
  ScratchDir dir("gltf-spec-gloss-textures");
  write_texel_bytes(dir.file("diffuse.png"), 1, 1, 3, {200, 100, 50});
  std::vector<float> rgba = {10, 20, 30, 255, 40, 50, 60, 51};
  for (float& v : rgba) v /= 255;
  write_test_image(dir.file("sg.png"), 2, 1, {"R", "G", "B", "A"}, rgba);
  std::string material =
      "{\"extensions\":{\"KHR_materials_pbrSpecularGlossiness\":{\"diffuseTexture\":{\"index\":0},"
      "\"specularGlossinessTexture\":{\"index\":1,\"texCoord\":0},\"glossinessFactor\":0.5}}}";
  std::string more = ",\"images\":[{\"uri\":\"diffuse.png\"},{\"uri\":\"sg.png\"}],"
                     "\"samplers\":[{\"wrapS\":33071}],\"textures\":[{\"source\":0},{\"source\":1,\"sampler\":0}]";
  SceneDesc scene = load_scene(dir.write("t.gltf", spec_gloss_file(material, more)).string());
  const MaterialDesc& m = scene.materials.at(0);
  CHECK(m.base_color_texture.texture == 0);
  CHECK(m.specular_color_texture.texture == 1);
  REQUIRE(m.metallic_roughness_texture.valid());
  CHECK(m.roughness == 1);  // all in the texture: 1 - 0.5 × alpha
  const TextureDesc& roughness = scene.textures.at(size_t(m.metallic_roughness_texture.texture));
  CHECK(roughness.wrap_s == TextureWrap::clamp_to_edge);  // the specular-glossiness texture's sampler
  const ImageDesc& image = scene.images.at(size_t(roughness.image));
  CHECK(image.channels == 1);
  CHECK(image.texels8 == std::vector<uint8_t>{127, 229});  // 255 - round(0.5 × 255), 255 - round(0.5 × 51)
}
