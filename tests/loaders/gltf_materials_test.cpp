// glTF materials, textures and samplers to MaterialDesc.
#include <doctest/doctest.h>

#include <algorithm>

#include "loaders/gltf_builder.h"
#include "load_scene.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

// A 2x1 RGB PNG: red then blue.
static void write_png(const std::filesystem::path& path) { write_texel_bytes(path, 2, 1, 3, {255, 0, 0, 0, 0, 255}); }

TEST_CASE("gltf materials: factors, textures, samplers and the supported extensions") {
  ScratchDir dir("gltf-materials");
  write_png(dir.file("albedo.png"));
  GltfBuilder b = quad_builder();
  b.floats({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2", 2);  // glTF v runs down the image
  std::string body =
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"TEXCOORD_0\":2},\"indices\":1,\"material\":0},"
      "{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
      "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],"
      "\"images\":[{\"uri\":\"albedo.png\"}],\"samplers\":[{\"magFilter\":9728,\"wrapS\":33071,\"wrapT\":33648}],"
      "\"textures\":[{\"source\":0,\"sampler\":0}],"
      "\"materials\":[{\"name\":\"paint\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.5,0.25,1,0.75],"
      "\"metallicFactor\":0.1,\"roughnessFactor\":0.3,\"baseColorTexture\":{\"index\":0,\"extensions\":{"
      "\"KHR_texture_transform\":{\"offset\":[0.5,0],\"scale\":[2,2],\"rotation\":0.25,\"texCoord\":1}}}},"
      "\"normalTexture\":{\"index\":0,\"scale\":0.5},\"emissiveFactor\":[1,0.5,0],\"alphaMode\":\"MASK\","
      "\"alphaCutoff\":0.25,\"doubleSided\":true,\"extensions\":{\"KHR_materials_emissive_strength\":"
      "{\"emissiveStrength\":4},\"KHR_materials_transmission\":{\"transmissionFactor\":0.9},"
      "\"KHR_materials_ior\":{\"ior\":1.33},\"KHR_materials_unlit\":{},\"KHR_materials_specular\":"
      "{\"specularFactor\":0.3,\"specularTexture\":{\"index\":0},\"specularColorFactor\":[2,1,0.5],"
      "\"specularColorTexture\":{\"index\":0,\"texCoord\":1}},\"KHR_materials_clearcoat\":{\"clearcoatFactor\":0.7,"
      "\"clearcoatRoughnessFactor\":0.2,\"clearcoatTexture\":{\"index\":0},\"clearcoatRoughnessTexture\":{\"index\":0},"
      "\"clearcoatNormalTexture\":{\"index\":0,\"scale\":0.75}},\"KHR_materials_sheen\":{\"sheenColorFactor\":[0.9,0.1,0.3],"
      "\"sheenRoughnessFactor\":0.6,\"sheenColorTexture\":{\"index\":0},\"sheenRoughnessTexture\":{\"index\":0}},"
      "\"KHR_materials_volume\":{\"thicknessFactor\":0.05,\"attenuationDistance\":2.5,\"attenuationColor\":[0.9,0.8,0.7]},"
      "\"KHR_materials_iridescence\":{\"iridescenceFactor\":0.6,\"iridescenceIor\":1.8,\"iridescenceThicknessMinimum\":200,"
      "\"iridescenceThicknessMaximum\":700,\"iridescenceThicknessTexture\":{\"index\":0}},"
      "\"KHR_materials_anisotropy\":{\"anisotropyStrength\":0.7,\"anisotropyRotation\":1.25,\"anisotropyTexture\":{\"index\":0}},"
      "\"KHR_materials_dispersion\":{\"dispersion\":0.36}}}]";
  SceneDesc scene = load_scene(dir.write("m.gltf", b.gltf(body)).string());
  REQUIRE(scene.materials.size() == 2);
  const MaterialDesc& m = scene.materials[0];
  CHECK(m.model == MaterialModel::metallic_roughness);
  CHECK(m.base_color.y == 0.25f);
  CHECK(m.alpha == 0.75f);
  CHECK(m.metallic == doctest::Approx(0.1));
  CHECK(m.roughness == doctest::Approx(0.3));
  CHECK(m.base_color_texture.texture == 0);
  CHECK(m.base_color_texture.texcoord == 1);
  CHECK(m.base_color_texture.offset.x == 0.5f);
  CHECK(m.base_color_texture.scale.y == 2);
  CHECK(m.base_color_texture.rotation == 0.25f);
  CHECK(m.normal_scale == 0.5f);
  CHECK(m.emission.x == 4);
  CHECK(m.emission.y == 2);
  CHECK(m.alpha_mode == AlphaMode::mask);
  CHECK(m.alpha_cutoff == 0.25f);
  CHECK(m.transmission == doctest::Approx(0.9));
  CHECK(m.ior == doctest::Approx(1.33));
  CHECK(m.unlit);
  CHECK(m.specular == doctest::Approx(0.3));
  CHECK(m.specular_color == color3{2, 1, 0.5f});
  CHECK(m.specular_strength_texture.texture == 0);
  CHECK(m.specular_color_texture.texcoord == 1);
  CHECK(m.clearcoat == doctest::Approx(0.7));
  CHECK(m.clearcoat_roughness == doctest::Approx(0.2));
  CHECK(m.clearcoat_texture.texture == 0);
  CHECK(m.clearcoat_roughness_texture.texture == 0);
  CHECK(m.clearcoat_normal_texture.texture == 0);  // the coat's own normal map, read, not warned about
  CHECK(m.clearcoat_normal_scale == 0.75f);
  CHECK(std::none_of(scene.warnings.begin(), scene.warnings.end(),
                     [](const std::string& w) { return w.find("clearcoatNormalTexture") != std::string::npos; }));
  CHECK(scene.materials[1].specular == 1);  // the default material has the full Fresnel layer
  CHECK(m.sheen_color == color3{0.9f, 0.1f, 0.3f});
  CHECK(m.sheen_roughness == doctest::Approx(0.6));
  CHECK(m.sheen_color_texture.texture == 0);
  CHECK(m.sheen_roughness_texture.texture == 0);
  CHECK(m.thickness == doctest::Approx(0.05));
  CHECK(m.attenuation_distance == 2.5f);
  CHECK(m.attenuation_color == color3{0.9f, 0.8f, 0.7f});
  CHECK(scene.materials[1].attenuation_distance == 0);  // infinite: no absorption
  CHECK(m.iridescence == doctest::Approx(0.6));
  CHECK(m.iridescence_ior == doctest::Approx(1.8));
  CHECK(m.iridescence_thickness_min == 200);
  CHECK(m.iridescence_thickness_max == 700);
  CHECK(m.iridescence_thickness_texture.texture == 0);
  CHECK_FALSE(m.iridescence_texture.valid());
  CHECK(scene.materials[1].iridescence == 0);
  CHECK(m.anisotropy_strength == doctest::Approx(0.7));
  CHECK(m.anisotropy_rotation == doctest::Approx(1.25));
  CHECK(m.anisotropy_texture.texture == 0);
  CHECK(m.dispersion == doctest::Approx(0.36));
  CHECK(scene.materials[1].dispersion == 0);
  CHECK(scene.materials[1].clearcoat == 0);
  CHECK(is_black(scene.materials[1].sheen_color));
  CHECK_FALSE(scene.materials[1].specular_color_texture.valid());
  CHECK(scene.materials[1].name == "glTF default");
  CHECK(scene.meshes[1].material == 1);
  REQUIRE(scene.textures.size() == 1);
  CHECK(scene.textures[0].filter == TextureFilter::nearest);
  CHECK(scene.textures[0].wrap_s == TextureWrap::clamp_to_edge);
  CHECK(scene.textures[0].wrap_t == TextureWrap::mirrored_repeat);
  REQUIRE(scene.images.size() == 1);
  CHECK(scene.images[0].width == 2);
  CHECK(scene.images[0].channels == 3);
  CHECK(scene.images[0].texels8 == std::vector<uint8_t>{255, 0, 0, 0, 0, 255});
  // The normal map asks for tangents: generated along +u, on the flat (unshared) vertices glTF
  // asks for when NORMAL is missing.
  REQUIRE(scene.meshes[0].tangents.size() == 6);
  CHECK(scene.meshes[0].tangents[0].x == doctest::Approx(1));
  CHECK(scene.meshes[0].tangents[0].w == -1);  // v grows along -y: a left-handed frame
}

TEST_CASE("gltf materials: an image that is not PNG or JPEG is refused by name") {
  ScratchDir dir("gltf-bad-image");
  dir.write("fake.png", "not an image at all");
  std::string path = dir.write("m.gltf", quad_builder().gltf(std::string(quad_mesh) +
      ",\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],\"images\":[{\"uri\":\"fake.png\"}]")).string();
  CHECK_THROWS_WITH_AS(load_scene(path), (path + ": images[0]: not a PNG or JPEG image").c_str(), LoadError);
}

TEST_CASE("gltf: a normal-mapped primitive without NORMAL gets flat normals on unshared vertices and ignores its TANGENT") {
  ScratchDir dir("gltf-flat-normal-map");
  write_png(dir.file("bumps.png"));
  GltfBuilder b = quad_builder();
  b.floats({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2", 2);
  b.floats({0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1}, "VEC4", 4);  // tangents along +y: must be ignored
  std::string body =
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"TEXCOORD_0\":2,\"TANGENT\":3},"
      "\"indices\":1,\"material\":0}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],"
      "\"images\":[{\"uri\":\"bumps.png\"}],\"textures\":[{\"source\":0}],"
      "\"materials\":[{\"normalTexture\":{\"index\":0}}]";
  SceneDesc scene = load_scene(dir.write("m.gltf", b.gltf(body)).string());
  REQUIRE(scene.meshes.size() == 1);
  const MeshDesc& mesh = scene.meshes[0];
  CHECK(mesh.positions.size() == 6);  // two triangles, three vertices each
  REQUIRE(mesh.normals.size() == 6);
  REQUIRE(mesh.tangents.size() == 6);
  for (size_t i = 0; i < 6; ++i) {
    CHECK(mesh.normals[i].z == doctest::Approx(1));
    CHECK(mesh.tangents[i].x == doctest::Approx(1));  // generated along +u = +x
  }
}

TEST_CASE("gltf materials: KHR_materials_variants picks each primitive's material by --variant name") {
  ScratchDir dir("gltf-variants");
  GltfBuilder b = quad_builder();
  std::string body =
      "\"materials\":[{\"name\":\"plain\"},{\"name\":\"red\"},{\"name\":\"blue\"}],"
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,\"material\":0,"
      "\"extensions\":{\"KHR_materials_variants\":{\"mappings\":[{\"material\":1,\"variants\":[0]},"
      "{\"material\":2,\"variants\":[1,2]}]}}}]}],"
      "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],\"extensionsUsed\":[\"KHR_materials_variants\"],"
      "\"extensions\":{\"KHR_materials_variants\":{\"variants\":[{\"name\":\"red shoe\"},{\"name\":\"blue shoe\"},"
      "{\"name\":\"night\"}]}}";
  std::string path = dir.write("v.gltf", b.gltf(body)).string();
  auto material_name = [&](const std::string& variant) {
    LoadOptions options;
    options.material_variant = variant;
    SceneDesc scene = load_scene(path, options);
    CHECK(scene.warnings.empty());
    return scene.materials.at(size_t(scene.meshes.at(0).material)).name;
  };
  CHECK(material_name("") == "plain");
  CHECK(material_name("red shoe") == "red");
  CHECK(material_name("blue shoe") == "blue");
  CHECK(material_name("night") == "blue");
  LoadOptions unknown;
  unknown.material_variant = "green";
  CHECK_THROWS_WITH_AS(load_scene(path, unknown),
                       (path + ": no material variant 'green' (variants: red shoe, blue shoe, night)").c_str(), LoadError);
  std::string plain = dir.write("plain.gltf", quad_builder().gltf(std::string(quad_mesh) + ",\"nodes\":[{\"mesh\":0}],"
                                                                  "\"scenes\":[{\"nodes\":[0]}]")).string();
  CHECK_THROWS_WITH_AS(load_scene(plain, unknown),
                       (plain + ": no material variant 'green' (the file has no KHR_materials_variants)").c_str(),
                       LoadError);
  std::string obj = dir.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").string();
  CHECK_THROWS_WITH_AS(load_scene(obj, unknown),
                       (obj + ": material variants (--variant) are a glTF extension (KHR_materials_variants)").c_str(),
                       LoadError);
}

TEST_CASE("gltf materials: a variant mapping to a material out of range names its place") {
  ScratchDir dir("gltf-variant-range");
  GltfBuilder b = quad_builder();
  std::string body =
      "\"materials\":[{}],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,"
      "\"extensions\":{\"KHR_materials_variants\":{\"mappings\":[{\"material\":5,\"variants\":[0]}]}}}]}],"
      "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],"
      "\"extensions\":{\"KHR_materials_variants\":{\"variants\":[{\"name\":\"a\"}]}}";
  std::string path = dir.write("v.gltf", b.gltf(body)).string();
  LoadOptions options;
  options.material_variant = "a";
  CHECK_THROWS_WITH_AS(load_scene(path, options),
                       (path + ": meshes[0].primitives[0].extensions.KHR_materials_variants.mappings[0].material: "
                               "material 5 out of range (1 materials)").c_str(),
                       LoadError);
}
