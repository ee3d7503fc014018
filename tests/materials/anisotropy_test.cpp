// KHR_materials_anisotropy: GGX stretched along a direction of the tangent frame.
#include <doctest/doctest.h>

#include "bsdf_test_configs.h"

namespace radiant::test {
namespace {

constexpr vec3 up = {0, 0, 1};

TEST_CASE("anisotropy: the highlight stretches along the anisotropy direction, and follows the tangent") {
  SurfaceMaterial brushed = anisotropic(metallic_roughness({0.9f, 0.9f, 0.9f}, 1, 0.2f), 0.9f);
  vec3 wo = up;
  // Directions 40 degrees off the mirror direction, along x and along y.
  vec3 along_x = spherical_direction(std::cos(0.7f), 0), along_y = spherical_direction(std::cos(0.7f), pi / 2);
  Bsdf x_brushed(brushed, up, wo, {1, 0, 0});
  CHECK(max_component(x_brushed.eval(along_x)) > 5 * max_component(x_brushed.eval(along_y)));
  // The same material brushed along y: the lobe turns with the tangent.
  Bsdf y_brushed(brushed, up, wo, {0, 1, 0});
  CHECK(max_component(y_brushed.eval(along_y)) == doctest::Approx(max_component(x_brushed.eval(along_x))).epsilon(1e-4));
  // Strength 0 is the isotropic model, bit for bit, whatever the tangent.
  SurfaceMaterial plain = metallic_roughness({0.9f, 0.9f, 0.9f}, 1, 0.2f);
  CHECK(Bsdf(anisotropic(plain, 0), up, wo, {1, 0, 0}).eval(along_x) == Bsdf(plain, up, wo).eval(along_x));
}

float white_metal_albedo(const SurfaceMaterial& m, float cos_wo) {
  UniformRandom random(51);
  color3 sum;
  for (int k = 0; k < 20000; ++k)
    if (auto s = Bsdf(m, up, spherical_direction(cos_wo, 0.4f), {1, 0, 0}).sample(random.next(), random.next2()))
      sum += s->weight;
  return sum.x / 20000;
}

TEST_CASE("anisotropy: white furnace, an anisotropic white metal keeps nearly all light") {
  // Roughness 0.3: alpha 0.09 across; along, 0.09 + 0.91 s^2 (0.17 at s = 0.3, 1 at s = 1). The
  // multiple scattering is tabulated for isotropic lobes and taken at the mean of the two alphas:
  // close, not exact. Single scattering alone kept 0.65 head on at s = 1.
  for (float strength : {0.3f, 1.0f})
    for (float cos_wo : {1.0f, 0.5f, 0.1f}) {
      SurfaceMaterial m = anisotropic(metallic_roughness({1, 1, 1}, 1, 0.3f), strength);
      float albedo = white_metal_albedo(m, cos_wo);
      INFO("strength ", strength, " cos(wo) ", cos_wo, ": ", albedo);
      CHECK(albedo <= 1.02f);
      CHECK(albedo >= 0.85f);
    }
}

}  // namespace
}  // namespace radiant::test
