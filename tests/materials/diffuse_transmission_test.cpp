// KHR_materials_diffuse_transmission: a share of the diffuse base leaves Lambertian into the other
// hemisphere, tinted, taking its energy from the diffuse reflection and nothing from the specular.
#include <doctest/doctest.h>

#include "bsdf_test_configs.h"
#include "support/scene_builders.h"

namespace radiant::test {
namespace {

constexpr vec3 up = {0, 0, 1};

// Directional albedo split by the side the sampled direction leaves: above and below the surface.
struct SplitAlbedo {
  color3 reflected, transmitted;
};
SplitAlbedo split_albedo(const SurfaceMaterial& m, vec3 wo, int samples, unsigned seed) {
  UniformRandom random(seed);
  SplitAlbedo out;
  for (int k = 0; k < samples; ++k) {
    float u_lobe = random.next();
    auto s = Bsdf(m, up, wo).sample(u_lobe, random.next2());
    if (!s) continue;
    (s->wi.z > 0 ? out.reflected : out.transmitted) += s->weight;
  }
  out.reflected = out.reflected / float(samples);
  out.transmitted = out.transmitted / float(samples);
  return out;
}

TEST_CASE("diffuse transmission: white furnace, reflected and transmitted light sum to all of it") {
  for (float roughness : {0.2f, 0.5f, 1.0f})
    for (float cos_o : {1.0f, 0.6f, 0.2f}) {
      vec3 wo = spherical_direction(cos_o, 0.3f);
      SplitAlbedo a = split_albedo(diffuse_transmitting(metallic_roughness({1, 1, 1}, 0, roughness), 1, {1, 1, 1}), wo,
                                   40000, 21);
      INFO("roughness ", roughness, " cos(wo) ", cos_o, ": reflected ", a.reflected.x, ", transmitted ", a.transmitted.x);
      float total = a.reflected.x + a.transmitted.x;
      CHECK(total >= 0.98f);
      CHECK(total <= 1.01f);
      // Factor 1 sends the whole diffuse base through; only the specular coating reflects.
      CHECK(a.transmitted.x > 0.5f);
      CHECK(a.transmitted.x == doctest::Approx(a.transmitted.z).epsilon(1e-5));
    }
}

TEST_CASE("diffuse transmission: an exactly Lambertian base splits by the factor, tinted by the colour") {
  vec3 wo = spherical_direction(0.7f, 1);
  SplitAlbedo all = split_albedo(diffuse_transmitting(gltf_lambert({1, 1, 1}), 1, {1, 1, 1}), wo, 4000, 3);
  CHECK(all.reflected.x == 0);
  CHECK(all.transmitted.x == doctest::Approx(1).epsilon(1e-5));
  SplitAlbedo tinted = split_albedo(diffuse_transmitting(gltf_lambert({0.8f, 0.8f, 0.8f}), 0.25f, {1, 0.5f, 0}), wo,
                                    40000, 4);
  // The spec's mix: (1 − 0.25) of the base colour reflects, 0.25 of the transmission colour passes.
  CHECK(tinted.reflected.x == doctest::Approx(0.75 * 0.8).epsilon(0.02));
  CHECK(tinted.transmitted.x == doctest::Approx(0.25).epsilon(0.02));
  CHECK(tinted.transmitted.y == doctest::Approx(0.125).epsilon(0.02));
  CHECK(tinted.transmitted.z == 0);
}

TEST_CASE("diffuse transmission: the transmitted lobe is Lambertian and reciprocal across the surface") {
  SurfaceMaterial m = diffuse_transmitting(metallic_roughness({0.7f, 0.7f, 0.7f}, 0, 0.4f), 0.6f, {0.9f, 0.6f, 0.3f});
  UniformRandom random(17);
  for (int k = 0; k < 100; ++k) {
    vec3 wo = spherical_direction(0.05f + 0.95f * random.next(), 2 * pi * random.next());
    vec3 wi = spherical_direction(0.05f + 0.95f * random.next(), 2 * pi * random.next());
    wi.z = -wi.z;
    // Seen from wi's side the surface's normal faces wi (the integrator flips it for opaque hits).
    color3 forward = Bsdf(m, up, wo).eval(wi) / std::abs(wi.z);
    color3 backward = Bsdf(m, -up, wi).eval(wo) / wo.z;
    CHECK(forward.x > 0);
    CHECK(forward.x == doctest::Approx(backward.x).epsilon(1e-3));
    CHECK(forward.z == doctest::Approx(backward.z).epsilon(1e-3));
  }
  // Without the extension nothing passes.
  SurfaceMaterial opaque = metallic_roughness({0.7f, 0.7f, 0.7f}, 0, 0.4f);
  CHECK(is_black(Bsdf(opaque, up, spherical_direction(0.8f, 0)).eval({0, 0, -1})));
}

// A white leaf (1 × 1 quad facing the camera, exactly Lambertian) lit only by a point light 1
// behind its centre: the side the camera sees is lit through the leaf alone.
SceneDesc backlit_leaf(float diffuse_transmission) {
  SceneDesc scene;
  MaterialDesc leaf;
  leaf.model = MaterialModel::metallic_roughness;
  leaf.base_color = {1, 1, 1};
  leaf.metallic = 0;
  leaf.specular = 0;
  leaf.diffuse_transmission = diffuse_transmission;
  leaf.diffuse_transmission_color = {1, 0.8f, 0.5f};
  add_quad(scene, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, add_material(scene, leaf));
  scene.lights.push_back(point_light({0, 0, -1}, {1, 1, 1}));
  scene.cameras.push_back(ortho_camera({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 2));
  return scene;
}

RenderOptions small_path_render(color3 environment) {
  RenderOptions o;
  o.width = 17;
  o.height = 17;
  o.spp = 16;
  o.mode = RenderMode::path;
  o.env_color = environment;
  return o;
}

TEST_CASE("diffuse transmission: a leaf lit from behind shows the light on its unlit side") {
  color3 without = pixel_mean(render_scene(backlit_leaf(0), small_path_render({0, 0, 0})).film.at(8, 8));
  color3 with = pixel_mean(render_scene(backlit_leaf(0.5f), small_path_render({0, 0, 0})).film.at(8, 8));
  CHECK(is_black(without));
  // Irradiance 1 behind the centre, half of it passed on Lambertian, tinted: 0.5 × colour / π
  // (the pixel's 1/17 width darkens its mean by about 0.3 %).
  CHECK(with.x == doctest::Approx(0.5 * inv_pi).epsilon(0.01));
  CHECK(with.y == doctest::Approx(0.5 * 0.8 * inv_pi).epsilon(0.01));
  CHECK(with.z == doctest::Approx(0.5 * 0.5 * inv_pi).epsilon(0.01));
}

TEST_CASE("diffuse transmission: a thin white leaf in a white furnace stays white") {
  SceneDesc scene = backlit_leaf(0.5f);
  scene.lights.clear();
  scene.materials[0].diffuse_transmission_color = {1, 1, 1};
  color3 leaf = pixel_mean(render_scene(scene, small_path_render({1, 1, 1})).film.at(8, 8));
  // Half reflected from the camera's side, half passed from behind.
  CHECK(leaf.x == doctest::Approx(1).epsilon(0.02));
  CHECK(leaf.z == doctest::Approx(1).epsilon(0.02));
}

}  // namespace
}  // namespace radiant::test
