// KHR_materials_dispersion: the spec's IOR per wavelength, and a tilted glass interface that
// bends each colour channel by Snell's law with its own wavelength's IOR.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "materials/dispersion.h"
#include "support/scene_builders.h"

namespace radiant {
namespace {

using test::render_scene;

TEST_CASE("dispersion: n(587.6 nm) is the material's IOR and n_F - n_C is (n_d - 1) / V_d") {
  float ior = 1.5f, dispersion = 0.5f;  // V_d = 40
  CHECK(dispersive_ior(ior, dispersion, 587.6f) == doctest::Approx(ior).epsilon(1e-4));
  float spread = dispersive_ior(ior, dispersion, 486.1f) - dispersive_ior(ior, dispersion, 656.3f);
  CHECK(spread == doctest::Approx((ior - 1) / 40).epsilon(0.01));
  CHECK(dispersive_ior(ior, 0, 400) == ior);  // no dispersion: exactly the IOR
  CHECK(dispersive_ior(1.1f, 100, 700) == 1.0f);  // never below 1
  // Red bends least, blue most.
  CHECK(dispersive_ior(ior, 1, channel_wavelengths_nm[0]) < dispersive_ior(ior, 1, channel_wavelengths_nm[1]));
  CHECK(dispersive_ior(ior, 1, channel_wavelengths_nm[1]) < dispersive_ior(ior, 1, channel_wavelengths_nm[2]));
}

// An orthographic camera looking down -z through a glass interface tilted 60 degrees about y, at
// an unlit white half plane x > edge at z = -depth inside the glass: each channel sees the half
// plane's edge where its refracted rays reach x = edge (near the image centre for green).
constexpr float tilt = pi / 3, depth = 4, edge = 1.9f;
constexpr int width = 64;

SceneDesc tilted_interface(float dispersion) {
  SceneDesc scene;
  MaterialDesc glass;
  glass.model = MaterialModel::metallic_roughness;
  glass.metallic = 0, glass.roughness = 0, glass.transmission = 1, glass.ior = 1.5f;
  glass.dispersion = dispersion;
  int g = test::add_material(scene, glass);
  float t = std::tan(tilt), e = 1.5f;
  test::add_quad(scene, {-e, -e, -e * t}, {e, -e, e * t}, {e, e, e * t}, {-e, e, -e * t}, g);
  MaterialDesc white;
  white.model = MaterialModel::metallic_roughness;
  white.unlit = true;
  int w = test::add_material(scene, white);
  test::add_quad(scene, {edge, -10, -depth}, {20, -10, -depth}, {20, 10, -depth}, {edge, 10, -depth}, w);
  scene.cameras.push_back(test::ortho_camera({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 2.0f / 8));
  return scene;
}

// The columns (of `width` over x in [-1, 1]) whose camera ray reaches x > edge at z = -depth after
// refracting with index `ior` at the interface.
int predicted_lit_columns(float ior) {
  vec3 n = {-std::sin(tilt), 0, std::cos(tilt)}, d = {0, 0, -1};
  float eta = 1 / ior, cos_i = -dot(d, n);
  float cos_t = std::sqrt(1 - eta * eta * (1 - cos_i * cos_i));
  vec3 refracted = d * eta + n * (eta * cos_i - cos_t);
  int lit = 0;
  for (int column = 0; column < width; ++column) {
    float x = -1 + (column + 0.5f) * 2 / width, z = x * std::tan(tilt);
    lit += x + refracted.x * (-depth - z) / refracted.z > edge;
  }
  return lit;
}

// Per channel, the columns whose mean over the rows exceeds half the brightest column's.
std::array<int, 3> measured_lit_columns(const Film& film) {
  std::array<int, 3> lit = {0, 0, 0};
  for (int c = 0; c < 3; ++c) {
    std::vector<double> column_mean(size_t(film.width), 0.0);
    for (int x = 0; x < film.width; ++x)
      for (int y = 0; y < film.height; ++y) column_mean[size_t(x)] += pixel_mean(film.at(x, y))[c] / film.height;
    double brightest = *std::max_element(column_mean.begin(), column_mean.end());
    for (double mean : column_mean) lit[size_t(c)] += mean > brightest / 2;
  }
  return lit;
}

TEST_CASE("dispersion: each channel refracts with its own wavelength's IOR, dispersion 0 bends all alike") {
  RenderOptions o;
  o.width = width, o.height = 8, o.spp = 48, o.max_depth = 4;
  o.mode = RenderMode::path;
  o.quiet = true;
  float dispersion = 5;  // exaggerated (V_d = 4) so that the channels part by pixels
  std::array<int, 3> lit = measured_lit_columns(render_scene(tilted_interface(dispersion), o).film);
  for (int c = 0; c < 3; ++c) {
    CAPTURE(c);
    int expected = predicted_lit_columns(dispersive_ior(1.5f, dispersion, channel_wavelengths_nm[c]));
    CHECK(std::abs(lit[size_t(c)] - expected) <= 1);
  }
  CHECK(lit[2] - lit[0] >= 3);  // blue and red part by several columns
  std::array<int, 3> plain = measured_lit_columns(render_scene(tilted_interface(0), o).film);
  int expected = predicted_lit_columns(1.5f);
  for (int c = 0; c < 3; ++c) CHECK(std::abs(plain[size_t(c)] - expected) <= 1);
  CHECK(plain[0] == plain[2]);
}

}  // namespace
}  // namespace radiant
