// Which way an environment map faces (its centre at +x, as in Blender and three.js), how
// --env-rotation and --up turn it, and the built-in studio's light.
#include <doctest/doctest.h>

#include <cmath>

#include "lights/environment_light.h"
#include "sampling/sampler.h"
#include "support/scene_builders.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// An 8x4 map, black but for one texel of radiance 1: column `x`, row `y`.
std::filesystem::path one_texel_map(const ScratchDir& dir, int x, int y) {
  std::vector<float> pixels(8 * 4 * 3, 0.0f);
  for (int c = 0; c < 3; ++c) pixels[(size_t(y) * 8 + x) * 3 + c] = 1;
  std::filesystem::path path = dir.file("map-" + std::to_string(x) + "-" + std::to_string(y) + ".exr");
  write_test_image(path, 8, 4, {"R", "G", "B"}, pixels);
  return path;
}

LightTable map_table(const std::filesystem::path& map, vec3 up, float rotation) {
  SceneDesc scene;
  EnvironmentSpec spec;
  spec.map_path = map.string();
  spec.frame = make_environment_frame(up, rotation);
  return make_light_table(scene, spec, true);
}

// Directions through the middle of texels of an 8x4 map in its own frame (y up, the centre +x):
// column 4 spans azimuths [0, 45) degrees from +x towards +z, column 6 [90, 135); row 0 spans
// [0, 45) degrees from straight up, row 1 [45, 90). Worked out by hand, not by radiant's code.
constexpr vec3 centre_texel = {0.853553f, 0.382683f, 0.353553f};   // column 4, row 1
constexpr vec3 quarter_texel = {-0.353553f, 0.382683f, 0.853553f};  // column 6, row 1
constexpr vec3 top_texel = {0.353553f, 0.923880f, -0.146447f};      // column 3, row 0

}  // namespace

TEST_CASE("environment: the map's centre faces +x, a quarter turn on faces +z, the top row is up") {
  ScratchDir dir("env-frame");
  LightTable centre = map_table(one_texel_map(dir, 4, 1), {0, 1, 0}, 0);
  CHECK(eval_environment(centre, centre_texel).x == 1);
  CHECK(eval_environment(centre, -centre_texel).x == 0);
  CHECK(eval_environment(centre, quarter_texel).x == 0);
  CHECK(eval_environment(map_table(one_texel_map(dir, 6, 1), {0, 1, 0}, 0), quarter_texel).x == 1);
  CHECK(eval_environment(map_table(one_texel_map(dir, 3, 0), {0, 1, 0}, 0), top_texel).x == 1);
}

TEST_CASE("environment: --env-rotation turns the map counterclockwise seen from above, --up +Z stands it on z") {
  ScratchDir dir("env-turn");
  std::filesystem::path centre = one_texel_map(dir, 4, 1), quarter = one_texel_map(dir, 6, 1);
  // A quarter turn counterclockwise seen from above (right-handed about +y) takes +x to -z and +z to +x.
  vec3 c = centre_texel;
  CHECK(eval_environment(map_table(centre, {0, 1, 0}, 90), {c.z, c.y, -c.x}).x == 1);
  CHECK(eval_environment(map_table(centre, {0, 1, 0}, 90), c).x == 0);
  CHECK(eval_environment(map_table(centre, {0, 1, 0}, -90), {-c.z, c.y, c.x}).x == 1);
  // z up as Blender has it: the map's up is +z, its centre still +x, and its +z is -y.
  auto z_up = [](vec3 d) { return vec3{d.x, -d.z, d.y}; };
  CHECK(eval_environment(map_table(centre, {0, 0, 1}, 0), z_up(centre_texel)).x == 1);
  CHECK(eval_environment(map_table(quarter, {0, 0, 1}, 0), z_up(quarter_texel)).x == 1);
  CHECK(eval_environment(map_table(one_texel_map(dir, 3, 0), {0, 0, 1}, 0), z_up(top_texel)).x == 1);
  CHECK(eval_environment(map_table(centre, {0, 0, 1}, 0), centre_texel).x == 0);
}

TEST_CASE("environment: sampling a turned map finds its lit texel, with the pdf it reports") {
  ScratchDir dir("env-turn-sampling");
  for (vec3 up : {vec3{0, 1, 0}, vec3{0, 0, 1}, normalize(vec3{1, 1, 0})})
    for (float rotation : {0.0f, 37.0f, -120.0f}) {
      CAPTURE(up.x);
      CAPTURE(up.z);
      CAPTURE(rotation);
      LightTable lights = map_table(one_texel_map(dir, 5, 2), up, rotation);
      for (uint32_t i = 0; i < 64; ++i) {
        vec3 d;
        float pdf = sample_environment(lights, up, 0.5f, {float(i % 8 + 0.5f) / 8, float(i / 8 + 0.5f) / 8}, d);
        REQUIRE(pdf > 0);
        CHECK(eval_environment(lights, d).x == 1);
        CHECK(environment_pdf(lights, up, d) == doctest::Approx(pdf).epsilon(1e-4));
      }
    }
}

TEST_CASE("environment: the studio lights a white diffuse floor from above near 0.9 and its underside far less") {
  // A white Lambertian square seen from above and from below, direct light only: radiance is
  // the cosine-weighted mean of the studio over the facing hemisphere.
  auto floor_radiance = [](float facing) {
    SceneDesc scene;
    int white = add_diffuse(scene, {1, 1, 1});
    vec3 a{-1, 0, -1}, b{1, 0, -1}, c{1, 0, 1}, d{-1, 0, 1};
    if (facing > 0) add_quad(scene, a, d, c, b, white);
    else add_quad(scene, a, b, c, d, white);
    scene.cameras.push_back(ortho_camera({0, 2 * facing, 0}, {0, -facing, 0}, {0, 0, -1}, 1));
    RenderOptions o;
    o.width = o.height = 8, o.spp = 256, o.mode = RenderMode::path, o.max_depth = 1;
    o.env_preset = EnvironmentPreset::studio;
    RenderResult r = render_scene(scene, o);
    double sum = 0;
    for (const FilmPixel& p : r.film.pixels) sum += pixel_mean(p).y;
    return sum / double(r.film.pixels.size());
  };
  // What the map says: the cosine-weighted sum of its texels over each hemisphere, divided by pi.
  EnvironmentSpec spec;
  spec.studio = true;
  LightTable studio = make_light_table(SceneDesc{}, spec, true);
  const EnvironmentMap& map = studio.environment_map;
  double up = 0, down = 0;
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      float sin_theta;
      vec3 d = environment_direction({(x + 0.5f) / map.width, (y + 0.5f) / map.height}, sin_theta);
      double solid_angle = 2 * pi * pi * sin_theta / (double(map.width) * map.height);
      double weighted = map.texels[size_t(y) * map.width + x].y * solid_angle * std::abs(d.y) / pi;
      (d.y > 0 ? up : down) += weighted;
    }
  double lit = floor_radiance(1), under = floor_radiance(-1);
  CHECK(lit == doctest::Approx(up).epsilon(0.03));
  CHECK(under == doctest::Approx(down).epsilon(0.03));
  CHECK(lit > 0.8);  // bright, and white is not clipped
  CHECK(lit < 1.0);
  CHECK(under < 0.5 * lit);
}
