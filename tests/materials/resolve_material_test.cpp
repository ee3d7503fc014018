// Material resolution (textures and vertex colors applied), the Whitted mapping of
// metallic-roughness onto Phong, and normal mapping.
#include <doctest/doctest.h>

#include "materials/surface.h"

namespace radiant {
namespace {

// Appends a 1x1 texture holding `texels` (float, so values are exact) and returns its ref.
TextureRef add_texture(SceneDesc& scene, std::vector<float> texels) {
  ImageDesc image;
  image.width = image.height = 1;
  image.channels = int(texels.size());
  image.texels_float = std::move(texels);
  scene.images.push_back(image);
  TextureDesc texture;
  texture.image = int(scene.images.size()) - 1;
  scene.textures.push_back(texture);
  TextureRef ref;
  ref.texture = int(scene.textures.size()) - 1;
  return ref;
}

// A 1x1 8-bit RGBA texture, for the sRGB decode of color slots.
TextureRef add_texture8(SceneDesc& scene, std::vector<uint8_t> texels) {
  TextureRef ref = add_texture(scene, {});
  ImageDesc& image = scene.images.back();
  image.channels = int(texels.size());
  image.texels8 = std::move(texels);
  return ref;
}

TEST_CASE("resolve metallic-roughness: factors times textures times vertex color") {
  SceneDesc scene;
  MaterialDesc material;
  material.model = MaterialModel::metallic_roughness;
  material.base_color = {0.5f, 1, 1};
  material.alpha = 0.8f;
  material.alpha_mode = AlphaMode::blend;
  material.base_color_texture = add_texture8(scene, {128, 255, 255, 255});
  material.metallic = 0.5f;
  material.roughness = 0.8f;
  material.metallic_roughness_texture = add_texture(scene, {0, 0.5f, 0.4f});  // G roughness, B metallic
  material.transmission = 0.5f;
  material.transmission_texture = add_texture(scene, {0.5f});
  material.emission = {2, 2, 2};
  material.emission_texture = add_texture8(scene, {128, 255, 0});
  material.ior = 1.33f;
  material.specular = 0.8f;
  material.specular_strength_texture = add_texture(scene, {1, 1, 1, 0.25f});  // A channel
  material.specular_color = {2, 1, 1};
  material.specular_color_texture = add_texture8(scene, {128, 255, 0});       // sRGB
  material.clearcoat = 0.5f;
  material.clearcoat_texture = add_texture(scene, {0.5f, 1, 1});              // R channel
  material.clearcoat_roughness = 0.8f;
  material.clearcoat_roughness_texture = add_texture(scene, {1, 0.25f, 1});   // G channel
  SurfaceAttributes attributes;
  attributes.vertex_color = {1, 0.5f, 1, 0.5f};
  SurfaceMaterial m = resolve_material(scene, material, attributes);
  CHECK(m.specular == doctest::Approx(0.2f));
  CHECK(m.specular_color.x == doctest::Approx(2 * 0.2158605f));
  CHECK(m.specular_color.y == doctest::Approx(1));
  CHECK(m.specular_color.z == 0);
  CHECK(m.clearcoat == doctest::Approx(0.25f));
  CHECK(m.clearcoat_roughness == doctest::Approx(0.2f));
  CHECK(m.model == MaterialModel::metallic_roughness);
  CHECK(m.base_color.x == doctest::Approx(0.5f * 0.2158605f));
  CHECK(m.base_color.y == doctest::Approx(0.5f));
  CHECK(m.base_color.z == doctest::Approx(1));
  CHECK(m.opacity == doctest::Approx(0.4f));
  CHECK(m.metallic == doctest::Approx(0.2f));
  CHECK(m.roughness == doctest::Approx(0.4f));
  CHECK(m.transmission == doctest::Approx(0.25f));
  CHECK(m.emission.x == doctest::Approx(2 * 0.2158605f));
  CHECK(m.emission.y == doctest::Approx(2));
  CHECK(m.emission.z == 0);
  CHECK(m.ior == 1.33f);
  CHECK_FALSE(m.has_normal_map);
  // The Phong fields are filled too, for the Whitted integrator.
  CHECK(m.kd.y == doctest::Approx(0.5f * 0.8f * 0.75f * (1 - 0.04f * 0.25f)));  // less the clearcoat's F0
}

TEST_CASE("resolve anisotropy: the texture's direction rotated by the rotation, its blue scaling the strength") {
  SceneDesc scene;
  MaterialDesc material;
  material.model = MaterialModel::metallic_roughness;
  material.anisotropy_strength = 0.8f;
  material.anisotropy_rotation = pi / 2;
  SurfaceMaterial plain = resolve_material(scene, material, {});
  CHECK(plain.anisotropy == doctest::Approx(0.8f));
  CHECK(plain.anisotropy_direction.x == doctest::Approx(0).epsilon(1e-6));  // the tangent turned a quarter
  CHECK(plain.anisotropy_direction.y == doctest::Approx(1));
  material.anisotropy_texture = add_texture(scene, {0.5f, 1, 0.5f});  // direction (0, 1), strength x 0.5
  material.anisotropy_rotation = pi / 2;
  SurfaceMaterial textured = resolve_material(scene, material, {});
  CHECK(textured.anisotropy == doctest::Approx(0.4f));
  CHECK(textured.anisotropy_direction.x == doctest::Approx(-1));
  CHECK(textured.anisotropy_direction.y == doctest::Approx(0).epsilon(1e-6));
}

TEST_CASE("resolve alpha modes: opaque ignores alpha, mask thresholds at the cutoff, blend keeps it") {
  SceneDesc scene;
  MaterialDesc material;
  material.model = MaterialModel::metallic_roughness;
  material.alpha = 0.6f;
  material.alpha_cutoff = 0.5f;
  material.alpha_mode = AlphaMode::opaque;
  CHECK(resolve_material(scene, material, {}).opacity == 1);
  material.alpha_mode = AlphaMode::mask;
  CHECK(resolve_material(scene, material, {}).opacity == 1);
  material.alpha_cutoff = 0.7f;
  CHECK(resolve_material(scene, material, {}).opacity == 0);
  material.alpha_mode = AlphaMode::blend;
  CHECK(resolve_material(scene, material, {}).opacity == doctest::Approx(0.6f));
}

TEST_CASE("resolve normal map: texels in 0..1 map to -1..1, xy scaled by normal_scale, normalized") {
  SceneDesc scene;
  MaterialDesc material;
  material.normal_texture = add_texture(scene, {0.75f, 0.5f, 1});
  material.normal_scale = 2;
  SurfaceMaterial m = resolve_material(scene, material, {});
  CHECK(m.has_normal_map);
  CHECK(m.normal_map_sample.x == doctest::Approx(std::sqrt(0.5f)));  // (0.5 * 2, 0, 1) normalized
  CHECK(m.normal_map_sample.y == doctest::Approx(0));
  CHECK(m.normal_map_sample.z == doctest::Approx(std::sqrt(0.5f)));
}

TEST_CASE("resolve phong: kd times map_Kd and vertex color, ks times map_Ks, map_d to opacity") {
  SceneDesc scene;
  MaterialDesc material;
  material.kd = {0.5f, 0.5f, 0.5f};
  material.base_color_texture = add_texture8(scene, {255, 128, 0});
  material.ks = {0.4f, 0.4f, 0.4f};
  material.specular_texture = add_texture(scene, {0.5f, 1, 0.25f});
  material.alpha_texture = add_texture(scene, {0.3f});
  material.alpha_mode = AlphaMode::blend;
  material.ka = {0.1f, 0.2f, 0.3f};
  material.kr = {0.25f, 0.25f, 0.25f};
  material.kt = {0.125f, 0.125f, 0.125f};
  material.shininess = 42;
  material.ior = 1.2f;
  material.emission = {1, 1, 1};
  SurfaceAttributes attributes;
  attributes.vertex_color = {1, 1, 0.5f, 1};
  SurfaceMaterial m = resolve_material(scene, material, attributes);
  CHECK(m.model == MaterialModel::phong);
  CHECK(m.kd.x == doctest::Approx(0.5f));
  CHECK(m.kd.y == doctest::Approx(0.5f * 0.2158605f));
  CHECK(m.kd.z == 0);
  CHECK(m.ks.x == doctest::Approx(0.2f));
  CHECK(m.ks.z == doctest::Approx(0.1f));
  CHECK(m.opacity == doctest::Approx(0.3f));
  CHECK(m.ka == material.ka);
  CHECK(m.kr == material.kr);
  CHECK(m.kt == material.kt);
  CHECK(m.shininess == 42);
  CHECK(m.ior == 1.2f);
  CHECK(m.emission == material.emission);
}

SurfaceMaterial mapped(color3 base, float metallic, float roughness, float transmission = 0, float specular = 1) {
  SurfaceMaterial m;
  m.model = MaterialModel::metallic_roughness;
  m.base_color = base, m.metallic = metallic, m.roughness = roughness, m.transmission = transmission;
  m.specular = specular;
  phong_from_metallic_roughness(m);
  return m;
}

TEST_CASE("whitted mapping: specularFactor 0 is kd = base color and nothing else") {
  color3 base = {0.8f, 0.5f, 0.2f};
  SurfaceMaterial m = mapped(base, 0, 1, 0, 0);
  CHECK(m.kd == base);
  CHECK(m.ks == color3{0, 0, 0});
  CHECK(m.kr == color3{0, 0, 0});
  CHECK(m.kt == color3{0, 0, 0});
}

TEST_CASE("whitted mapping: metals, glossy dielectrics and glass") {
  color3 gold = {1, 0.8f, 0.3f};
  SurfaceMaterial mirror = mapped(gold, 1, 0);
  CHECK(mirror.kd == color3{0, 0, 0});
  CHECK(mirror.ks == gold);
  CHECK(mirror.kr == gold);
  CHECK(mirror.shininess == 10000);
  SurfaceMaterial glossy = mapped({1, 1, 1}, 0, 0.5f);  // alpha = 0.25: 2 / alpha^2 - 2 = 30
  CHECK(glossy.shininess == doctest::Approx(30));
  CHECK(glossy.kr.x == doctest::Approx(0.04f * 0.25f));
  CHECK(glossy.ks.x == doctest::Approx(0.04f));
  CHECK(glossy.kd.x == 1);
  SurfaceMaterial glass = mapped({0.9f, 1, 1}, 0, 0, 1);
  CHECK(glass.kd == color3{0, 0, 0});
  CHECK(glass.kt.x == doctest::Approx(0.9f));
  CHECK(glass.kr.x == doctest::Approx(0.04f));
  CHECK(mapped({1, 1, 1}, 1, 1).shininess == 1);  // 2/1 - 2 = 0, clamped
}

TEST_CASE("normal map: tangent space (0,0,1) keeps n, x follows the tangent, w flips the bitangent") {
  vec3 n = {0, 0, 1};
  vec4 tangent = {1, 0, 0.3f, 1};  // not orthogonal to n: orthogonalized first
  vec3 same = apply_normal_map(n, tangent, {0, 0, 1});
  CHECK(same.z == doctest::Approx(1));
  vec3 along_tangent = apply_normal_map(n, tangent, {1, 0, 0});
  CHECK(along_tangent.x == doctest::Approx(1));
  CHECK(apply_normal_map(n, tangent, {0, 1, 0}).y == doctest::Approx(1));
  CHECK(apply_normal_map(n, {1, 0, 0, -1}, {0, 1, 0}).y == doctest::Approx(-1));
  vec3 no_tangent = apply_normal_map(n, {0, 0, 0, 1}, {0.6f, 0, 0.8f});
  CHECK(length(no_tangent) == doctest::Approx(1));
  CHECK(no_tangent.z == doctest::Approx(0.8f));
}

}  // namespace
}  // namespace radiant
