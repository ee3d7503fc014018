// KHR_materials_iridescence: thin-film interference in the Fresnel term of the metallic-roughness BSDF.
#include <doctest/doctest.h>

#include "bsdf_test_configs.h"
#include "materials/fresnel.h"
#include "materials/thin_film.h"

namespace radiant::test {
namespace {

constexpr vec3 up = {0, 0, 1};
constexpr color3 glass_f0 = {0.04f, 0.04f, 0.04f};

TEST_CASE("thin film: a quarter-wave film of index 1.3 on glass is an anti-reflection coating for green") {
  // Reflections at the top and at the base cancel at the wavelength whose quarter the film's
  // optical thickness is: ((1.5 - 1.3^2) / (1.5 + 1.3^2))^2 = 0.0035 instead of 0.04 at 550 nm.
  // Such a coating stays well below the bare glass over the whole visible range.
  color3 f = thin_film_fresnel(1, 1, {1.3f, 550 / (4 * 1.3f)}, glass_f0);
  INFO(f.x, " ", f.y, " ", f.z);
  CHECK(f.y < 0.01f);
  CHECK(max_component(f) < 0.015f);
  // Twice as thick, a half-wave film reflects green like the bare glass again (constructive).
  CHECK(thin_film_fresnel(1, 1, {1.3f, 550 / (2 * 1.3f)}, glass_f0).y > 0.025f);
}

TEST_CASE("thin film: head on, a film of the outside's own index leaves the base's reflectance") {
  // (Away from normal incidence the extension's Schlick approximation gives even this non-interface
  // a reflectance, (1 - cos)^5.)
  color3 f = thin_film_fresnel(1, 1, {1.0f, 300}, {0.9f, 0.6f, 0.3f});
  CHECK(f.x == doctest::Approx(0.9f).epsilon(0.01));
  CHECK(f.y == doctest::Approx(0.6f).epsilon(0.01));
  CHECK(f.z == doctest::Approx(0.3f).epsilon(0.01));
}

TEST_CASE("iridescence: the hue of a soap-bubble-like reflection follows the film's thickness, and factor 0 changes nothing") {
  SurfaceMaterial black = metallic_roughness({0, 0, 0}, 0, 0);  // a smooth black dielectric: only its mirror
  auto reflectance = [&](float thickness) {
    auto s = Bsdf(iridescent(black, 1, 1.8f, thickness), up, up).sample(0.5f, {0.5f, 0.5f});
    REQUIRE(s.has_value());
    return s->weight * s->pdf;
  };
  color3 thin = reflectance(250), thick = reflectance(450);
  INFO(thin.x, " ", thin.y, " ", thin.z, " / ", thick.x, " ", thick.y, " ", thick.z);
  // Another colour, not only another brightness: the channels' proportions differ.
  CHECK(max_component(abs(thin / mean(thin) - thick / mean(thick))) > 0.1f);
  CHECK(max_component(thin) <= 1);
  // Factor 0: the plain metal, bit for bit.
  vec3 wo = spherical_direction(0.6f, 0.3f), wi = spherical_direction(0.8f, 2.9f);
  SurfaceMaterial rough = metallic_roughness({0.9f, 0.6f, 0.3f}, 1, 0.4f);
  CHECK(Bsdf(iridescent(rough, 0, 1.8f, 300), up, wo).eval(wi) == Bsdf(rough, up, wo).eval(wi));
  // The Whitted mapping takes the film's normal-incidence colour for ks.
  color3 ks = iridescent(black, 1, 1.8f, 250).ks;
  CHECK(ks.x == doctest::Approx(thin.x).epsilon(1e-4));
  CHECK(ks.z == doctest::Approx(thin.z).epsilon(1e-4));
}

}  // namespace
}  // namespace radiant::test
