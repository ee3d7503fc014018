// The dielectric's Fresnel layer as the glTF BRDF defines it: no fade at roughness 1, and
// KHR_materials_specular's strength and F0 tint, in the path tracer's BSDF and the Whitted mapping.
#include <doctest/doctest.h>

#include "bsdf_test_configs.h"
#include "materials/fresnel.h"

namespace radiant::test {
namespace {

constexpr vec3 up = {0, 0, 1};

color3 albedo(const SurfaceMaterial& m, vec3 wo, int samples = 40000) {
  return directional_albedo(m, up, wo, samples, 21);
}

// The reflectance of a smooth black dielectric's mirror lobe at wo (its only lobe).
color3 mirror_reflectance(const SurfaceMaterial& m, vec3 wo) {
  auto s = Bsdf(m, up, wo).sample(0.5f, {0.5f, 0.5f});
  REQUIRE(s.has_value());
  REQUIRE(s->delta);
  return s->weight * s->pdf;
}

TEST_CASE("specular layer: a rough black dielectric keeps its Fresnel reflection at roughness 1") {
  // The glTF BRDF has no fade: under a white sky a black plastic shows its coating, about 1 % head
  // on (F0 = 4 %, of which single-scattering GGX at alpha 1 keeps a third).
  SurfaceMaterial black = metallic_roughness({0, 0, 0}, 0, 1);
  color3 head_on = albedo(black, up);
  CHECK(head_on.x > 0.01f);
  CHECK(head_on.x < 0.04f);
  CHECK(head_on.x == doctest::Approx(head_on.z));
  // Towards grazing the layer reflects more, as Fresnel says.
  CHECK(albedo(black, spherical_direction(0.2f, 0)).x > head_on.x);
  // With specularFactor 0 the same surface is black.
  CHECK(is_black(albedo(gltf_lambert({0, 0, 0}), up)));
}

TEST_CASE("specular layer: strength and F0 tint scale a smooth dielectric's reflection") {
  color3 tint = {2, 1, 0.25f};
  SurfaceMaterial plain = specular_dielectric({0, 0, 0}, 0, 1, {1, 1, 1});
  SurfaceMaterial tinted = specular_dielectric({0, 0, 0}, 0, 0.5f, tint);
  CHECK(is_pure_delta(tinted));
  color3 f0 = mirror_reflectance(plain, up);
  CHECK(f0.x == doctest::Approx(0.04f));
  color3 f0_tinted = mirror_reflectance(tinted, up);
  CHECK(f0_tinted.x == doctest::Approx(0.5f * 0.08f));
  CHECK(f0_tinted.y == doctest::Approx(0.5f * 0.04f));
  CHECK(f0_tinted.z == doctest::Approx(0.5f * 0.01f));
  // The tint is a normal-incidence colour: at 60 degrees each channel follows the exact Fresnel
  // curve rescaled from its F0 to 1 at grazing.
  float cos60 = 0.5f, exact = fresnel_dielectric(cos60, 1.5f);
  float rise = (exact - 0.04f) / 0.96f;
  color3 oblique = mirror_reflectance(tinted, spherical_direction(cos60, 0));
  CHECK(oblique.x == doctest::Approx(0.5f * (0.08f + 0.92f * rise)));
  CHECK(oblique.z == doctest::Approx(0.5f * (0.01f + 0.99f * rise)));
  CHECK(mirror_reflectance(plain, spherical_direction(cos60, 0)).y == doctest::Approx(exact));
  // F0 saturates at 1: a specular colour of 40 turns the coating into a mirror.
  CHECK(mirror_reflectance(specular_dielectric({0, 0, 0}, 0, 1, {40, 40, 40}), up).x == doctest::Approx(1));
}

TEST_CASE("specular layer: white furnace, the coating trades diffuse for specular without gain or loss") {
  // A white base under its coating: whatever the layer reflects the diffuse base does not get.
  for (float roughness : {0.0f, 0.3f, 1.0f})
    for (float specular : {0.0f, 0.5f, 1.0f})
      for (color3 tint : {color3{1, 1, 1}, color3{3, 1, 0}})
        for (float cos_wo : {1.0f, 0.5f, 0.1f}) {
          SurfaceMaterial m = specular_dielectric({1, 1, 1}, roughness, specular, tint);
          color3 a = albedo(m, spherical_direction(cos_wo, 0.3f), 20000);
          INFO("roughness ", roughness, " specular ", specular, " cos(wo) ", cos_wo, ": ", a.x, " ", a.y, " ", a.z);
          CHECK(max_component(a) <= 1.005f);
          // The diffuse gets what the coating's brightest channel does not reflect, multiple
          // scattering included (microfacet_energy.h): that channel reflects everything. Single
          // scattering with the glTF BRDF's layering kept 0.36 at roughness 1, cos 0.1.
          CHECK(max_component(a) >= 0.98f);
          if (tint.z == 1) CHECK(min_component(a) >= 0.98f);
          if (specular == 0) CHECK(a.x == doctest::Approx(1).epsilon(1e-5));
        }
}

TEST_CASE("whitted mapping: the specular layer's F0 becomes ks and, on smooth surfaces, kr") {
  SurfaceMaterial rough = metallic_roughness({0.5f, 0.5f, 0.5f}, 0, 1);
  CHECK(rough.ks.x == doctest::Approx(0.04f));  // no fade: the highlight stays at roughness 1
  CHECK(rough.kr.x == 0);                        // but a rough surface mirrors nothing
  SurfaceMaterial tinted = specular_dielectric({0.5f, 0.5f, 0.5f}, 0, 0.5f, {2, 1, 0});
  CHECK(tinted.ks.x == doctest::Approx(0.04f));
  CHECK(tinted.ks.y == doctest::Approx(0.02f));
  CHECK(tinted.ks.z == 0);
  CHECK(tinted.kr.x == doctest::Approx(0.04f));
  CHECK(tinted.kd.x == doctest::Approx(0.5f));
}

}  // namespace
}  // namespace radiant::test
