// KHR_materials_clearcoat: the coat's Fresnel reflection and the share it leaves the base, in the
// path tracer's BSDF and the Whitted mapping.
#include <doctest/doctest.h>

#include "bsdf_test_configs.h"
#include "materials/fresnel.h"

namespace radiant::test {
namespace {

constexpr vec3 up = {0, 0, 1};

color3 albedo(const SurfaceMaterial& m, vec3 wo, int samples = 20000) {
  return directional_albedo(m, up, wo, samples, 31);
}

TEST_CASE("clearcoat: a smooth coat over a black base is a dielectric mirror of ior 1.5 times the factor") {
  SurfaceMaterial coat = coated(specular_dielectric({0, 0, 0}, 0, 0, {1, 1, 1}), 0.8f, 0);
  CHECK(is_pure_delta(coat));
  for (float cos_wo : {1.0f, 0.5f, 0.1f}) {
    vec3 wo = spherical_direction(cos_wo, 0.4f);
    auto s = Bsdf(coat, up, wo).sample(0.3f, {0.5f, 0.5f});
    REQUIRE(s.has_value());
    CHECK(s->delta);
    CHECK(s->wi.z == doctest::Approx(wo.z));
    CHECK(s->weight.x * s->pdf == doctest::Approx(0.8f * fresnel_dielectric(cos_wo, 1.5f)));
  }
}

TEST_CASE("clearcoat: the base below gets what the coat lets through, in and out") {
  color3 base = {0.6f, 0.4f, 0.2f};
  SurfaceMaterial coat = coated(gltf_lambert(base), 1, 0);  // smooth: eval sees only the base
  CHECK_FALSE(is_pure_delta(coat));
  vec3 wo = spherical_direction(0.7f, 1), wi = spherical_direction(0.3f, 2.5f);
  color3 f = Bsdf(coat, up, wo).eval(wi);
  float through = (1 - fresnel_dielectric(0.7f, 1.5f)) * (1 - fresnel_dielectric(0.3f, 1.5f));
  CHECK(f.x == doctest::Approx(0.6f / pi * 0.3f * through));
  CHECK(f.z == doctest::Approx(0.2f / pi * 0.3f * through));
  // Factor 0 is no coat at all: the plain model, the same values.
  SurfaceMaterial uncoated = coated(metallic_roughness(base, 0.3f, 0.4f), 0, 0.2f);
  SurfaceMaterial plain = metallic_roughness(base, 0.3f, 0.4f);
  CHECK(Bsdf(uncoated, up, wo).eval(wi) == Bsdf(plain, up, wo).eval(wi));
}

TEST_CASE("clearcoat: white furnace, coat plus base never exceed 1 and lose only what the layering drops") {
  // Over a white mirror: F + (1 - F)^2 = 1 - F (1 - F), at most a quarter lost (F = 1/2).
  for (float cos_wo : {1.0f, 0.5f, 0.1f}) {
    SurfaceMaterial coat_on_mirror = coated(metallic_roughness({1, 1, 1}, 1, 0), 1, 0);
    float f = fresnel_dielectric(cos_wo, 1.5f);
    CHECK(albedo(coat_on_mirror, spherical_direction(cos_wo, 0)).x == doctest::Approx(1 - f * (1 - f)).epsilon(0.01));
  }
  for (float coat_roughness : {0.0f, 0.3f, 0.8f})
    for (float factor : {0.25f, 1.0f})
      for (float cos_wo : {1.0f, 0.5f, 0.1f}) {
        SurfaceMaterial m = coated(gltf_lambert({1, 1, 1}), factor, coat_roughness);
        color3 a = albedo(m, spherical_direction(cos_wo, 0.2f));
        INFO("coat roughness ", coat_roughness, " factor ", factor, " cos(wo) ", cos_wo, ": ", a.x);
        CHECK(a.x <= 1.005f);
        if (cos_wo >= 0.5f) CHECK(a.x >= 0.7f);  // grazing light on a rough coat is lost much more
      }
}

TEST_CASE("clearcoat: a coat normal of its own turns the coat's mirror and the Fresnel the base sees") {
  vec3 coat_normal = normalize(vec3{0.3f, 0, 1});
  vec3 wo = up;
  SurfaceMaterial mirror_coat = coated(specular_dielectric({0, 0, 0}, 0, 0, {1, 1, 1}), 1, 0);
  auto s = Bsdf(mirror_coat, up, wo, {}, coat_normal).sample(0.3f, {0.5f, 0.5f});
  REQUIRE(s.has_value());
  CHECK(s->delta);
  vec3 mirrored = coat_normal * (2 * dot(coat_normal, wo)) - wo;  // about the coat's normal, not the base's
  CHECK(s->wi.x == doctest::Approx(mirrored.x));
  CHECK(s->wi.z == doctest::Approx(mirrored.z));
  CHECK(s->weight.x * s->pdf == doctest::Approx(fresnel_dielectric(dot(coat_normal, wo), 1.5f)));
  // A smooth coat over Lambert: the base keeps its own normal for the cosine, the coat's
  // Fresnel is taken against the coat's normal on the way in and out.
  color3 base = {0.6f, 0.4f, 0.2f};
  SurfaceMaterial coat = coated(gltf_lambert(base), 1, 0);
  vec3 wi = spherical_direction(0.5f, 2.5f);
  color3 f = Bsdf(coat, up, wo, {}, coat_normal).eval(wi);
  float through = (1 - fresnel_dielectric(dot(coat_normal, wo), 1.5f)) * (1 - fresnel_dielectric(dot(coat_normal, wi), 1.5f));
  CHECK(f.x == doctest::Approx(0.6f / pi * wi.z * through));
  // The same normal as the base's is no tilt at all.
  CHECK(Bsdf(coat, up, wo, {}, up).eval(wi) == Bsdf(coat, up, wo).eval(wi));
}

TEST_CASE("clearcoat: a tilted rough coat still samples consistently and conserves energy") {
  vec3 coat_normal = normalize(vec3{-0.4f, 0.2f, 1});
  SurfaceMaterial m = coated(gltf_lambert({1, 1, 1}), 1, 0.3f);
  UniformRandom random(5);
  color3 sum;
  int samples = 20000;
  for (float cos_wo : {0.9f, 0.4f}) {
    vec3 wo = spherical_direction(cos_wo, 0.3f);
    Bsdf bsdf(m, up, wo, {}, coat_normal);
    sum = {};
    for (int k = 0; k < samples; ++k) {
      float u_lobe = random.next();
      auto s = bsdf.sample(u_lobe, random.next2());
      if (!s) continue;
      sum += s->weight;
      if (k % 100 != 0) continue;
      float pdf = bsdf.pdf(s->wi);
      CHECK(pdf == doctest::Approx(s->pdf).epsilon(1e-3));
      color3 weight = bsdf.eval(s->wi) / pdf;
      CHECK(weight.x == doctest::Approx(s->weight.x).epsilon(1e-3));
    }
    color3 albedo = sum / float(samples);
    INFO("cos(wo) ", cos_wo, ": ", albedo.x);
    CHECK(albedo.x <= 1.005f);
    CHECK(albedo.x >= 0.6f);
  }
}

TEST_CASE("whitted mapping: the coat's F0 joins the highlight and the mirror, taken from the layers below") {
  SurfaceMaterial m = coated(gltf_lambert({0.5f, 0.5f, 0.5f}), 1, 0);
  CHECK(m.kd.x == doctest::Approx(0.5f * 0.96f));
  CHECK(m.ks.x == doctest::Approx(0.04f));
  CHECK(m.kr.x == doctest::Approx(0.04f));
  SurfaceMaterial rough = coated(gltf_lambert({0.5f, 0.5f, 0.5f}), 0.5f, 1);
  CHECK(rough.ks.x == doctest::Approx(0.02f));
  CHECK(rough.kr.x == 0);
}

}  // namespace
}  // namespace radiant::test
