// Physical properties of every BSDF configuration: energy conservation, reciprocity, and the
// consistency of eval, pdf and sample that next-event estimation and MIS rely on.
#include <doctest/doctest.h>

#include "bsdf_test_configs.h"

namespace radiant::test {
namespace {

constexpr float wo_cosines[] = {1.0f, 0.8f, 0.5f, 0.2f, 0.02f};

std::vector<BsdfConfig> all_configs() {
  std::vector<BsdfConfig> configs = non_delta_configs();
  for (const BsdfConfig& config : delta_configs()) configs.push_back(config);
  return configs;
}

TEST_CASE("bsdf energy: directional albedo never exceeds 1") {
  unsigned seed = 7;
  for (const BsdfConfig& config : all_configs()) {
    for (float cos_wo : wo_cosines) {
      vec3 wo = config_wo(config, cos_wo);
      color3 albedo = directional_albedo(config.material, {0, 0, 1}, wo, 20000, seed++);
      INFO(config.name, ", cos(wo) = ", cos_wo, ", albedo = ", albedo.x, " ", albedo.y, " ", albedo.z);
      CHECK(max_component(albedo) <= 1.01f);
      CHECK(min_component(albedo) >= 0);
    }
  }
}

TEST_CASE("bsdf energy: white furnace, a white Lambertian reflects exactly everything") {
  SurfaceMaterial white = gltf_lambert({1, 1, 1});
  for (float cos_wo : wo_cosines) {
    color3 albedo = directional_albedo(white, {0, 0, 1}, spherical_direction(cos_wo, 1), 4000, 3);
    CHECK(albedo.x == doctest::Approx(1).epsilon(1e-5));
    CHECK(albedo.z == doctest::Approx(1).epsilon(1e-5));
  }
}

TEST_CASE("bsdf energy: lossless interfaces keep nearly all light") {
  // A smooth dielectric splits light into F and 1 - F; a white smooth metal reflects all.
  for (const BsdfConfig& config : delta_configs()) {
    if (config.name.find("smooth glass") == std::string::npos && config.name != "smooth metal") continue;
    for (float cos_wo : wo_cosines) {
      color3 albedo = directional_albedo(config.material, {0, 0, 1}, config_wo(config, cos_wo), 20000, 5);
      INFO(config.name, ", cos(wo) = ", cos_wo);
      CHECK(albedo.x == doctest::Approx(1).epsilon(0.01));
    }
  }
  // Rough white metal and rough glass lose only what single scattering misses.
  SurfaceMaterial rough_metal = metallic_roughness({1, 1, 1}, 1, 0.3f);
  CHECK(directional_albedo(rough_metal, {0, 0, 1}, spherical_direction(0.8f, 0), 20000, 9).x > 0.95f);
  SurfaceMaterial rough_glass = metallic_roughness({1, 1, 1}, 0, 0.3f, 1);
  CHECK(directional_albedo(rough_glass, {0, 0, 1}, spherical_direction(0.8f, 0), 20000, 9).x > 0.95f);
}

TEST_CASE("bsdf reciprocity: f(wo, wi) == f(wi, wo) for reflection") {
  UniformRandom random(11);
  vec3 n = normalize(vec3{0.3f, -0.2f, 0.9f});  // a tilted normal also checks the frame
  vec3 t, b;
  orthonormal_basis(n, t, b);
  auto world = [&](vec3 local) { return t * local.x + b * local.y + n * local.z; };
  for (const BsdfConfig& config : non_delta_configs()) {
    if (config.from_inside) continue;
    for (int k = 0; k < 200; ++k) {
      vec3 wo = world(spherical_direction(0.05f + 0.95f * random.next(), 2 * pi * random.next()));
      vec3 wi = world(spherical_direction(0.05f + 0.95f * random.next(), 2 * pi * random.next()));
      color3 forward = Bsdf(config.material, n, wo).eval(wi) / dot(n, wi);
      color3 backward = Bsdf(config.material, n, wi).eval(wo) / dot(n, wo);
      INFO(config.name);
      CHECK(forward.x == doctest::Approx(backward.x).epsilon(1e-3));
      CHECK(forward.z == doctest::Approx(backward.z).epsilon(1e-3));
    }
  }
}

TEST_CASE("bsdf consistency: weight is eval over pdf, eval and pdf vanish together, and eval with pdf is both") {
  vec3 n = normalize(vec3{-0.4f, 0.1f, 0.8f});
  vec3 t, b;
  orthonormal_basis(n, t, b);
  auto world = [&](vec3 local) { return t * local.x + b * local.y + n * local.z; };
  for (const BsdfConfig& config : all_configs()) {
    UniformRandom random(13);
    for (float cos_wo : wo_cosines) {
      vec3 wo = world(config_wo(config, cos_wo));
      for (int k = 0; k < 300; ++k) {
        float u_lobe = random.next();
        auto s = Bsdf(config.material, n, wo).sample(u_lobe, random.next2());
        INFO(config.name, ", cos(wo) = ", cos_wo);
        if (s && !s->delta) {
          color3 f = Bsdf(config.material, n, wo).eval(s->wi);
          float pdf = Bsdf(config.material, n, wo).pdf(s->wi);
          CHECK(pdf == doctest::Approx(s->pdf).epsilon(2e-3));
          CHECK(s->weight.x == doctest::Approx(f.x / pdf).epsilon(2e-3));
          CHECK(s->weight.y == doctest::Approx(f.y / pdf).epsilon(2e-3));
        }
        vec3 wi = world(spherical_direction(2 * random.next() - 1, 2 * pi * random.next()));
        bool scatters = !is_black(Bsdf(config.material, n, wo).eval(wi));
        bool sampled = Bsdf(config.material, n, wo).pdf(wi) > 0;
        CHECK(scatters == sampled);
        // Evaluated together (light sampling's MIS), both are what each gives alone, bit for bit.
        for (vec3 direction : {wi, s ? s->wi : wi}) {
          Bsdf bsdf(config.material, n, wo);
          float pdf_together = -1;
          color3 f_together = bsdf.eval(direction, pdf_together);
          color3 f_alone = bsdf.eval(direction);
          CHECK(f_together.x == f_alone.x);
          CHECK(f_together.y == f_alone.y);
          CHECK(f_together.z == f_alone.z);
          CHECK(pdf_together == bsdf.pdf(direction));
        }
      }
    }
  }
}

TEST_CASE("bsdf robustness: degenerate directions and parameters give finite values") {
  std::vector<SurfaceMaterial> materials;
  for (const BsdfConfig& config : all_configs()) materials.push_back(config.material);
  materials.push_back(metallic_roughness({0, 0, 0}, 0, 0));
  materials.push_back(metallic_roughness({1, 1, 1}, 0, 0, 1, 1));
  materials.push_back(phong({}, {1, 1, 1}, 0));
  materials.push_back(phong({}, {1, 1, 1}, 1e6f));
  vec3 n = {0, 0, 1};
  std::vector<vec3> directions = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {1, 0, 1e-8f}, {1, 0, -1e-8f},
                                  normalize(vec3{1, 1, 1e-4f}), {0, 0, 0}};
  UniformRandom random(17);
  for (const SurfaceMaterial& m : materials) {
    for (vec3 wo : directions) {
      for (vec3 wi : directions) {
        CHECK(is_finite(Bsdf(m, n, wo).eval(wi)));
        CHECK(std::isfinite(Bsdf(m, n, wo).pdf(wi)));
      }
      for (int k = 0; k < 50; ++k) {
        float u_lobe = random.next();
        auto s = Bsdf(m, n, wo).sample(u_lobe, random.next2());
        if (!s) continue;
        CHECK(is_finite(s->weight));
        CHECK(is_finite(s->wi));
        CHECK(std::isfinite(s->pdf));
      }
    }
  }
}

}  // namespace
}  // namespace radiant::test
