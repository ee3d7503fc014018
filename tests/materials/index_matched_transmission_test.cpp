// Rough transmission between equal indices (ior 1, Khronos' TransmissionRoughnessTest "Air"):
// the interface neither reflects nor bends light, whatever its roughness, and the rough lobe
// of an ior just above 1 closes in on that straight line.
#include <doctest/doctest.h>

#include "bsdf_test_configs.h"

namespace radiant::test {
namespace {

constexpr vec3 up = {0, 0, 1};
constexpr float roughnesses[] = {0, 0.3f, 0.6f, 1};
constexpr float wo_cosines[] = {1, 0.7f, 0.3f, 0.05f};

}  // namespace

TEST_CASE("index-matched transmission: white furnace, ior 1 passes everything straight through at any roughness") {
  unsigned seed = 1;
  for (float roughness : roughnesses) {
    SurfaceMaterial clear = metallic_roughness({1, 1, 1}, 0, roughness, 1, 1.0f);
    CHECK(is_pure_delta(clear));  // no light is reflected: next-event estimation has nothing to find
    for (float cos_wo : wo_cosines) {
      for (float side : {1.0f, -1.0f}) {
        vec3 wo = spherical_direction(cos_wo, 0.4f);
        wo.z *= side;
        INFO("roughness ", roughness, ", cos(wo) ", cos_wo, ", side ", side);
        CHECK(directional_albedo(clear, up, wo, 2000, seed++).x == doctest::Approx(1).epsilon(1e-5));
        UniformRandom random(seed++);
        for (int k = 0; k < 20; ++k) {
          auto s = Bsdf(clear, up, wo).sample(random.next(), random.next2());
          REQUIRE(s.has_value());
          CHECK(s->delta);
          CHECK(s->transmitted);
          CHECK(dot(s->wi, -wo) == doctest::Approx(1).epsilon(1e-6));
        }
        CHECK(is_black(Bsdf(clear, up, wo).eval(-wo)));
        CHECK(Bsdf(clear, up, wo).pdf(-wo) == 0);
      }
    }
  }
}

TEST_CASE("index-matched transmission: base colour tints it, and a metal share keeps its own rough lobe") {
  SurfaceMaterial tinted = metallic_roughness({0.9f, 0.5f, 0.2f}, 0, 0.6f, 1, 1.0f);
  color3 albedo = directional_albedo(tinted, up, spherical_direction(0.6f, 0), 2000, 3);
  CHECK(albedo.x == doctest::Approx(0.9f).epsilon(1e-4));
  CHECK(albedo.z == doctest::Approx(0.2f).epsilon(1e-4));
  // Half metal: the metal reflects through its GGX lobe, the glass half passes straight through.
  SurfaceMaterial half = metallic_roughness({1, 1, 1}, 0.5f, 0.6f, 1, 1.0f);
  CHECK_FALSE(is_pure_delta(half));
  UniformRandom random(5);
  int straight = 0, reflected = 0;
  for (int k = 0; k < 2000; ++k) {
    auto s = Bsdf(half, up, spherical_direction(0.6f, 0)).sample(random.next(), random.next2());
    if (!s) continue;
    if (s->delta) {
      ++straight;
      CHECK(s->transmitted);
    } else {
      ++reflected;
      CHECK(s->wi.z > 0);
    }
  }
  CHECK(straight > 500);
  CHECK(reflected > 500);
}

TEST_CASE("index-matched transmission: continuous in ior, the rough lobe just above 1 is nearly straight and keeps its energy") {
  vec3 wo = spherical_direction(0.7f, 0);
  for (float roughness : {0.3f, 0.6f}) {
    SurfaceMaterial near = metallic_roughness({1, 1, 1}, 0, roughness, 1, 1.01f);
    CHECK_FALSE(is_pure_delta(near));
    UniformRandom random(9);
    double alignment = 0, weight = 0;
    int transmitted = 0;
    for (int k = 0; k < 4000; ++k) {
      auto s = Bsdf(near, up, wo).sample(random.next(), random.next2());
      if (!s || !s->transmitted) continue;
      CHECK_FALSE(s->delta);
      alignment += dot(s->wi, -wo), weight += s->weight.x, ++transmitted;
    }
    INFO("roughness ", roughness);
    REQUIRE(transmitted > 3000);
    CHECK(alignment / transmitted > 0.999);  // within a few degrees of straight through
    // Albedo close to ior 1's: what differs is single scattering's loss (the microfacets' shadowing).
    CHECK(directional_albedo(near, up, wo, 20000, 11).x > 0.95f);
  }
}

}  // namespace radiant::test
