// Energy compensation of the metallic-roughness lobes (microfacet_energy.h): a white metal and a
// white dielectric reflect all the light of a white furnace at every roughness, as in Cycles and
// OpenPBR, while the albedo tables stay the single-scattering lobe's own.
#include <doctest/doctest.h>

#include "bsdf_test_configs.h"
#include "materials/microfacet.h"
#include "materials/microfacet_energy.h"

namespace radiant::test {
namespace {

constexpr vec3 up = {0, 0, 1};
constexpr float roughnesses[] = {0.0f, 0.1f, 0.25f, 0.5f, 0.75f, 1.0f};
constexpr float cosines[] = {1.0f, 0.7f, 0.4f, 0.15f};

// Single-scattering GGX albedo (Fresnel 1) by Monte Carlo over visible normals: the mean G2/G1.
float single_scattering_albedo(float cos_o, float alpha, int samples) {
  UniformRandom random(5);
  vec3 wo = spherical_direction(cos_o, 0);
  double sum = 0;
  for (int k = 0; k < samples; ++k) {
    vec3 wi = reflect(wo, sample_ggx_visible_normal(wo, alpha, random.next2()));
    if (wi.z > 0) sum += ggx_masking_shadowing(wo, wi, alpha) / ggx_masking(wo, alpha);
  }
  return float(sum / samples);
}

TEST_CASE("energy: the tabulated GGX albedo is the single-scattering lobe's") {
  microfacet_albedo_tables();
  for (float roughness : {0.2f, 0.5f, 0.8f, 1.0f})
    for (float cos_o : {1.0f, 0.6f, 0.3f}) {
      float table = ggx_albedo(cos_o, roughness);
      float monte_carlo = single_scattering_albedo(cos_o, roughness * roughness, 200000);
      INFO("roughness ", roughness, " cos ", cos_o, ": table ", table, ", Monte Carlo ", monte_carlo);
      CHECK(table == doctest::Approx(monte_carlo).epsilon(0.005));
    }
  // A mirror loses nothing; alpha 1 loses more than half head on.
  CHECK(ggx_albedo(0.5f, 0) == 1);
  CHECK(ggx_albedo_average(0) == 1);
  CHECK(ggx_albedo(1, 1) < 0.5f);
}

TEST_CASE("energy: white furnace, a white metal and a white dielectric reflect all light at any roughness") {
  for (float roughness : roughnesses)
    for (float cos_o : cosines) {
      vec3 wo = spherical_direction(cos_o, 0.4f);
      color3 metal = directional_albedo(metallic_roughness({1, 1, 1}, 1, roughness), up, wo, 40000, 3);
      color3 dielectric = directional_albedo(metallic_roughness({1, 1, 1}, 0, roughness), up, wo, 40000, 4);
      INFO("roughness ", roughness, " cos(wo) ", cos_o, ": metal ", metal.x, ", dielectric ", dielectric.x);
      CHECK(metal.x >= 0.98f);
      CHECK(metal.x <= 1.01f);
      CHECK(dielectric.x >= 0.98f);
      CHECK(dielectric.x <= 1.01f);
      CHECK(dielectric.x == dielectric.z);
    }
}

TEST_CASE("energy: an anisotropic white metal and a white plastic of another ior keep their energy") {
  for (float cos_o : cosines) {
    vec3 wo = spherical_direction(cos_o, 0.9f);
    color3 brushed = directional_albedo(anisotropic(metallic_roughness({1, 1, 1}, 1, 0.5f), 0.8f), up, wo, 40000, 6);
    color3 dense = directional_albedo(metallic_roughness({1, 1, 1}, 0, 0.6f, 0, 2.2f), up, wo, 40000, 7);
    INFO("cos(wo) ", cos_o, ": brushed ", brushed.x, ", ior 2.2 ", dense.x);
    // The table's effective alpha sqrt(ax·ay) is an approximation of the anisotropic loss.
    CHECK(brushed.x >= 0.95f);
    CHECK(brushed.x <= 1.01f);
    CHECK(dense.x >= 0.97f);
    CHECK(dense.x <= 1.01f);
  }
}

TEST_CASE("energy: a coloured rough metal gains more in its bright channels (Fresnel-aware multiple scattering)") {
  // Each bounce between microfacets reflects F_avg: the gain over single scattering grows like
  // F_avg², so the gold's blue channel gains less than its red one, relative to single scattering.
  color3 gold = {1.0f, 0.7f, 0.3f};
  vec3 wo = spherical_direction(0.8f, 0);
  color3 a = directional_albedo(metallic_roughness(gold, 1, 1), up, wo, 80000, 8);
  float white = directional_albedo(metallic_roughness({1, 1, 1}, 1, 1), up, wo, 80000, 8).x;
  CHECK(a.x == doctest::Approx(white).epsilon(0.01));
  float single = ggx_albedo(0.8f, 1);
  // Relative to single scattering's Fresnel-weighted albedo, the gain is at least F0 times.
  CHECK(a.z > 0.3f * single);
  CHECK(a.z / a.x < a.y / a.x);
  CHECK(a.z < 0.3f * white + 0.02f);
}

TEST_CASE("energy: the diffuse under the coating is reciprocal and takes what the coating does not reflect") {
  // eval(wo, wi)/cos(wi) is symmetric for the compensated lobes, at every roughness.
  UniformRandom random(12);
  for (float roughness : {0.3f, 1.0f})
    for (float metallic : {0.0f, 1.0f})
      for (int k = 0; k < 100; ++k) {
        SurfaceMaterial m = metallic_roughness({0.8f, 0.5f, 0.2f}, metallic, roughness);
        vec3 wo = spherical_direction(0.05f + 0.95f * random.next(), 2 * pi * random.next());
        vec3 wi = spherical_direction(0.05f + 0.95f * random.next(), 2 * pi * random.next());
        color3 forward = Bsdf(m, up, wo).eval(wi) / wi.z, backward = Bsdf(m, up, wi).eval(wo) / wo.z;
        CHECK(forward.x == doctest::Approx(backward.x).epsilon(1e-4));
        CHECK(forward.z == doctest::Approx(backward.z).epsilon(1e-4));
      }
  // A black base shows only its coating; a white one adds exactly what that coating lets through.
  for (float cos_o : cosines) {
    vec3 wo = spherical_direction(cos_o, 0);
    float coating = directional_albedo(metallic_roughness({0, 0, 0}, 0, 0.7f), up, wo, 40000, 9).x;
    float white = directional_albedo(metallic_roughness({1, 1, 1}, 0, 0.7f), up, wo, 40000, 9).x;
    float grey = directional_albedo(metallic_roughness({0.5f, 0.5f, 0.5f}, 0, 0.7f), up, wo, 40000, 9).x;
    INFO("cos(wo) ", cos_o, ": coating ", coating, ", white ", white, ", grey ", grey);
    CHECK(grey == doctest::Approx(coating + 0.5f * (white - coating)).epsilon(0.02));
  }
}

}  // namespace
}  // namespace radiant::test
