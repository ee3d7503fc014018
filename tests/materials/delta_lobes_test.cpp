// The delta lobes: mirrors and smooth interfaces of both models, seen from either side.
#include <doctest/doctest.h>

#include "bsdf_test_configs.h"

namespace radiant::test {
namespace {

constexpr vec3 up = {0, 0, 1};

// The only sample of a material whose lobes are all delta (u_lobe picks the first lobe).
BsdfSample only_sample(const SurfaceMaterial& m, vec3 n, vec3 wo, float u_lobe = 0.5f) {
  auto s = Bsdf(m, n, wo).sample(u_lobe, {0.3f, 0.6f});
  REQUIRE(s.has_value());
  CHECK(s->delta);
  return *s;
}

TEST_CASE("phong transmission: ior 1 passes straight through from either side") {
  SurfaceMaterial clear = phong({}, {}, 1, {}, {1, 1, 1}, 1);
  CHECK(is_pure_delta(clear));
  for (vec3 wo : {normalize(vec3{0.6f, 0.2f, 0.7f}), normalize(vec3{-0.1f, 0.5f, -0.4f})}) {
    BsdfSample s = only_sample(clear, up, wo);
    CHECK(s.transmitted);
    CHECK(s.wi.x == doctest::Approx(-wo.x));
    CHECK(s.wi.y == doctest::Approx(-wo.y));
    CHECK(s.wi.z == doctest::Approx(-wo.z));
    CHECK(s.weight.x == doctest::Approx(1));
    CHECK(s.pdf == 1);
  }
}

TEST_CASE("phong transmission: Snell's law entering, total internal reflection leaving") {
  SurfaceMaterial glass = phong({}, {}, 1, {}, {1, 1, 1}, 1.5f);
  // Entering at 60 degrees: sin(theta_t) = sin(60) / 1.5.
  vec3 outside = spherical_direction(std::cos(pi / 3), 0);
  BsdfSample in = only_sample(glass, up, outside);
  CHECK(in.transmitted);
  CHECK(in.wi.z < 0);
  CHECK(-in.wi.x == doctest::Approx(std::sin(pi / 3) / 1.5f));
  // Leaving at 30 degrees (below the 41.8 degree critical angle): sin(theta_t) = 1.5 sin(30).
  vec3 inside_below_critical = spherical_direction(std::cos(pi / 6), 0);
  inside_below_critical.z = -inside_below_critical.z;
  BsdfSample out = only_sample(glass, up, inside_below_critical);
  CHECK(out.transmitted);
  CHECK(out.wi.z > 0);
  CHECK(-out.wi.x == doctest::Approx(0.75f));
  // Leaving at 45 degrees: totally reflected back inside, with the whole transmission weight.
  vec3 inside_beyond_critical = normalize(vec3{1, 0, -1});
  BsdfSample reflected = only_sample(glass, up, inside_beyond_critical);
  CHECK_FALSE(reflected.transmitted);
  CHECK(reflected.wi.x == doctest::Approx(-inside_beyond_critical.x));
  CHECK(reflected.wi.z == doctest::Approx(inside_beyond_critical.z));
  CHECK(reflected.weight.x == doctest::Approx(1));
}

TEST_CASE("phong mirror: kr reflects about the normal, weighted by kr over its selection probability") {
  SurfaceMaterial mirror = phong({}, {}, 1, {0.9f, 0.5f, 0.1f});
  CHECK(is_pure_delta(mirror));
  vec3 wo = normalize(vec3{0.3f, -0.4f, 0.5f});
  BsdfSample s = only_sample(mirror, up, wo);
  CHECK_FALSE(s.transmitted);
  CHECK(s.wi.x == doctest::Approx(-wo.x));
  CHECK(s.wi.z == doctest::Approx(wo.z));
  CHECK(s.weight.x == doctest::Approx(0.9f));
  CHECK(s.weight.z == doctest::Approx(0.1f));
  CHECK(is_black(Bsdf(mirror, up, wo).eval(s.wi)));  // delta lobes are not evaluated
  CHECK(Bsdf(mirror, up, wo).pdf(s.wi) == 0);
}

TEST_CASE("phong energy: kd + ks + kr + kt above 1 is scaled down per channel") {
  SurfaceMaterial bright = phong({0.8f, 0.4f, 0}, {}, 1, {0.8f, 0, 0});
  vec3 wo = up;
  color3 f = Bsdf(bright, up, wo).eval(up);
  CHECK(f.x == doctest::Approx(0.5f / pi));  // 0.8 / (0.8 + 0.8)
  CHECK(f.y == doctest::Approx(0.4f / pi));  // untouched: 0.4 <= 1
  CHECK_FALSE(is_pure_delta(bright));
}

TEST_CASE("metallic-roughness smooth glass: Fresnel splits reflection and refraction") {
  SurfaceMaterial glass = metallic_roughness({1, 1, 1}, 0, 0, 1, 1.5f);
  CHECK(is_pure_delta(glass));
  vec3 wo = up;
  auto reflected = Bsdf(glass, up, wo).sample(0.0f, {0.5f, 0.5f});
  auto refracted = Bsdf(glass, up, wo).sample(0.999f, {0.5f, 0.5f});
  REQUIRE(reflected.has_value());
  REQUIRE(refracted.has_value());
  CHECK(reflected->weight.x * reflected->pdf == doctest::Approx(0.04f));  // F at normal incidence
  CHECK(refracted->weight.x * refracted->pdf == doctest::Approx(0.96f));
  CHECK(refracted->transmitted);
  CHECK(refracted->wi.z == doctest::Approx(-1));
  CHECK(reflected->pdf + refracted->pdf == doctest::Approx(1));
  // From inside beyond the critical angle every sample is a total reflection.
  for (float u_lobe : {0.0f, 0.5f, 0.999f}) {
    auto inside = Bsdf(glass, up, normalize(vec3{1, 0, -1})).sample(u_lobe, {0.5f, 0.5f});
    REQUIRE(inside.has_value());
    CHECK_FALSE(inside->transmitted);
    CHECK(inside->wi.z == doctest::Approx(-std::sqrt(0.5f)));
    CHECK(inside->weight.x == doctest::Approx(1));
  }
}

TEST_CASE("metallic-roughness: specularFactor 0 is exactly base color over pi") {
  SurfaceMaterial lambert = gltf_lambert({0.8f, 0.5f, 0.2f});
  vec3 wi = normalize(vec3{0.2f, 0.3f, 0.9f});
  color3 f = Bsdf(lambert, up, normalize(vec3{-0.5f, 0, 0.5f})).eval(wi);
  CHECK(f.x == doctest::Approx(0.8f / pi * wi.z));
  CHECK(f.z == doctest::Approx(0.2f / pi * wi.z));
  CHECK(bsdf_albedo(lambert) == color3{0.8f, 0.5f, 0.2f});
  CHECK_FALSE(is_pure_delta(lambert));
}

TEST_CASE("unlit materials scatter nothing") {
  SurfaceMaterial unlit = metallic_roughness({1, 1, 1}, 0, 1);
  unlit.unlit = true;
  CHECK(is_black(Bsdf(unlit, up, up).eval(up)));
  CHECK_FALSE(Bsdf(unlit, up, up).sample(0.5f, {0.5f, 0.5f}).has_value());
  CHECK(is_pure_delta(unlit));
}

TEST_CASE("a lobe is drawn only when there is a choice, and any draw then gives the same sample") {
  vec3 wo = normalize(vec3{0.3f, -0.2f, 0.9f});
  // One lobe each: Phong diffuse, a pure mirror.
  SurfaceMaterial matte;
  matte.kd = {0.5f, 0.5f, 0.5f};
  SurfaceMaterial mirror;
  mirror.kd = {0, 0, 0};
  mirror.kr = {1, 1, 1};
  for (const SurfaceMaterial& m : {matte, mirror}) {
    Bsdf bsdf(m, up, wo);
    CHECK_FALSE(bsdf.chooses_lobe());
    for (float u_lobe : {0.0f, 0.3f, 0.999f}) {
      auto a = bsdf.sample(u_lobe, {0.25f, 0.7f}), b = bsdf.sample(0.5f, {0.25f, 0.7f});
      REQUIRE(a.has_value());
      REQUIRE(b.has_value());
      CHECK(a->wi == b->wi);
      CHECK(a->weight == b->weight);
    }
  }
  // Two lobes: diffuse plus mirror, and the glTF plastic (coating over diffuse).
  SurfaceMaterial shiny = matte;
  shiny.kr = {0.3f, 0.3f, 0.3f};
  CHECK(Bsdf(shiny, up, wo).chooses_lobe());
  CHECK(Bsdf(metallic_roughness({0.8f, 0.5f, 0.2f}, 0, 0.5f), up, wo).chooses_lobe());
}

}  // namespace
}  // namespace radiant::test
