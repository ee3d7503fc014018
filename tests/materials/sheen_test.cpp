// KHR_materials_sheen: the Charlie sheen lobe, its tabulated albedo, and the share it leaves the base.
#include <doctest/doctest.h>

#include "bsdf_test_configs.h"
#include "materials/sheen.h"

namespace radiant::test {
namespace {

constexpr vec3 up = {0, 0, 1};

color3 albedo(const SurfaceMaterial& m, vec3 wo, int samples = 40000) {
  return directional_albedo(m, up, wo, samples, 41);
}

TEST_CASE("sheen: over a black base the surface reflects the sheen colour times the tabulated albedo E") {
  for (float roughness : {0.3f, 0.6f, 1.0f})
    for (float cos_wo : {1.0f, 0.5f, 0.15f}) {
      SurfaceMaterial velvet = sheened(gltf_lambert({0, 0, 0}), {1, 0.5f, 0}, roughness);
      color3 a = albedo(velvet, spherical_direction(cos_wo, 0.1f));
      float e = sheen_albedo(cos_wo, roughness);
      INFO("roughness ", roughness, " cos(wo) ", cos_wo, ": ", a.x, " vs E = ", e);
      CHECK(e > 0);
      CHECK(e < 1);
      CHECK(a.x == doctest::Approx(e).epsilon(0.04));
      CHECK(a.y == doctest::Approx(0.5f * e).epsilon(0.04));
      CHECK(a.z == 0);
    }
  // Cloth shines at grazing angles: more sheen towards the silhouette.
  CHECK(sheen_albedo(0.1f, 0.5f) > sheen_albedo(1, 0.5f));
}

TEST_CASE("sheen: white furnace, sheen plus base never exceed 1") {
  for (float roughness : {0.2f, 0.5f, 1.0f})
    for (float cos_wo : {1.0f, 0.5f, 0.1f}) {
      SurfaceMaterial m = sheened(gltf_lambert({1, 1, 1}), {1, 1, 1}, roughness);
      color3 a = albedo(m, spherical_direction(cos_wo, 0.6f), 20000);
      INFO("roughness ", roughness, " cos(wo) ", cos_wo, ": ", a.x);
      CHECK(a.x <= 1.005f);
      CHECK(a.x >= 0.6f);  // the extension's min() scaling drops what the sheen takes at the other angle
    }
}

TEST_CASE("sheen: the base below gets min(1 - max(colour) E(cos wo), 1 - max(colour) E(cos wi))") {
  color3 base = {0.5f, 0.5f, 0.5f};
  SurfaceMaterial m = sheened(gltf_lambert(base), {0.2f, 0.8f, 0.4f}, 0.7f);
  vec3 wo = spherical_direction(0.9f, 0), wi = spherical_direction(0.25f, 2);
  float scale = 1 - 0.8f * std::max(sheen_albedo(0.9f, 0.7f), sheen_albedo(0.25f, 0.7f));
  float sheen = eval_sheen(wo, wi, 0.7f);
  color3 f = Bsdf(m, up, wo).eval(wi);
  CHECK(f.x == doctest::Approx(0.5f / pi * 0.25f * scale + 0.2f * sheen));
  CHECK(f.y == doctest::Approx(0.5f / pi * 0.25f * scale + 0.8f * sheen));
  CHECK_FALSE(is_pure_delta(m));
}

}  // namespace
}  // namespace radiant::test
