// Rough glass of ior 1 (Khronos' TransmissionRoughnessTest "Air" row) in front of a bright sky:
// it neither reflects nor bends light, so it shows the sky behind it, whatever its roughness.
#include <doctest/doctest.h>

#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

TEST_CASE("render: rough transmission of ior 1 shows the bright background through it, not black") {
  for (float roughness : {0.3f, 1.0f}) {
    SceneDesc scene;
    MaterialDesc air;
    air.model = MaterialModel::metallic_roughness;
    air.base_color = {1, 1, 1};
    air.metallic = 0;
    air.roughness = roughness;
    air.transmission = 1;
    air.ior = 1;
    add_sphere(scene, {0, 0, 0}, 1, add_material(scene, air));
    scene.cameras.push_back(ortho_camera({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 4));
    RenderOptions o;
    o.width = o.height = 16;
    o.spp = 4;
    o.mode = RenderMode::path;
    o.env_color = color3{2, 2, 2};
    Film film = render_scene(scene, o).film;
    INFO("roughness ", roughness);
    for (int x : {6, 8, 10}) {  // inside the sphere's disc (radius 4 pixels around (8, 8))
      color3 through = pixel_mean(film.at(x, 8));
      CHECK(through.x == doctest::Approx(2).epsilon(1e-4));
      CHECK(through.z == doctest::Approx(2).epsilon(1e-4));
    }
  }
}
