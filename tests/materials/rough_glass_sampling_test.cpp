// Sampling rough glass (ior 1.5): the glass lobe reflects or refracts as its sampled microfacet's
// Fresnel says, so from inside, where many microfacets reflect totally, no sample carries a
// weight many times the albedo (the fireflies of choosing by the macro normal's Fresnel alone).
#include <doctest/doctest.h>

#include "bsdf_test_configs.h"

namespace radiant::test {

TEST_CASE("rough glass: sample weights stay near 1 from either side, past the critical angle too") {
  unsigned seed = 21;
  for (float roughness : {0.2f, 0.6f, 1.0f}) {
    SurfaceMaterial glass = metallic_roughness({1, 1, 1}, 0, roughness, 1, 1.5f);
    for (float cos_wo : {0.9f, 0.5f, 0.2f}) {  // inside, the critical angle's cosine is 0.745
      for (float side : {1.0f, -1.0f}) {
        vec3 wo = spherical_direction(cos_wo, 0.3f);
        wo.z *= side;
        const Bsdf bsdf(glass, {0, 0, 1}, wo);
        UniformRandom random(seed++);
        float largest = 0;
        int reflected = 0, transmitted = 0;
        for (int k = 0; k < 20000; ++k) {
          auto s = bsdf.sample(random.next(), random.next2());
          if (!s) continue;
          largest = std::max(largest, max_component(s->weight));
          ++(s->transmitted ? transmitted : reflected);
        }
        INFO("roughness ", roughness, ", cos(wo) ", cos_wo, ", side ", side);
        CHECK(largest < 2.5f);  // choosing by the macro normal's Fresnel gave weights up to 21
        CHECK(transmitted > 0);
        CHECK(reflected > 0);
      }
    }
  }
}

}  // namespace radiant::test
