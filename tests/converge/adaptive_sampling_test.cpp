// Adaptive sampling (--noise-threshold): where it puts samples, what it buys, and that it stays
// deterministic.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>

#include "converge/convergence.h"
#include "load_scene.h"
#include "support/scene_builders.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

// Left half: the uniform sky seen directly (no noise at all). Right half: a diffuse wall behind
// a diffuse ball, lit by that sky (noisy everywhere).
SceneDesc half_noisy_scene() {
  SceneDesc scene;
  int gray = add_diffuse(scene, {0.8f, 0.8f, 0.8f});
  add_quad(scene, {0, -1, 0}, {1, -1, 0}, {1, 1, 0}, {0, 1, 0}, gray);
  add_sphere(scene, {0.5f, 0, 0.5f}, 0.4f, gray);
  scene.cameras.push_back(ortho_camera({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 2));
  return scene;
}

RenderOptions half_noisy_options(int spp) {
  RenderOptions options;
  options.width = options.height = 32;
  options.spp = spp;
  options.mode = RenderMode::path;
  options.sampler = SamplerKind::random;
  options.env_color = color3{1, 1, 1};
  options.max_depth = 3;
  return options;
}


}  // namespace

TEST_CASE("adaptive: at equal total samples, --noise-threshold beats uniform sampling where noise is uneven") {
  SceneDesc scene = half_noisy_scene();
  PreparedScene prepared = prepare_scene(scene);
  Reference reference = render_reference(prepared, half_noisy_options(1), 1024);

  RenderOptions adaptive = half_noisy_options(64);
  adaptive.noise_threshold = 0.002f;  // only the noiseless sky gets under it
  adaptive.min_spp = 8;
  RenderResult a = render_prepared(prepared, adaptive);
  size_t pixels = a.film.pixels.size();
  CHECK(a.stats.min_pixel_samples == 8);  // the sky stops after its minimum samples
  CHECK(a.stats.max_pixel_samples == 64);
  CHECK(a.film.at(2, 16).samples == 8);
  CHECK(a.film.at(16, 10).samples == 64);  // the wall
  // The ball's front sees only sky and stops too, away from the wall's noisy pixels; a pixel
  // beside a noisy one goes on with it.
  CHECK(a.film.at(25, 16).samples == 8);
  CHECK(a.film.at(15, 16).samples == 64);  // sky, but beside the noisy wall

  int uniform_spp = int(a.stats.samples / pixels);  // the same budget, spread evenly
  CHECK(uniform_spp >= 20);
  CHECK(uniform_spp <= 40);
  RenderResult u = render_prepared(prepared, half_noisy_options(uniform_spp));
  CHECK(u.stats.samples <= a.stats.samples);
  double adaptive_rmse = measure_error(film_to_compare_image(a.film, false), reference.image, {}).rmse;
  double uniform_rmse = measure_error(film_to_compare_image(u.film, false), reference.image, {}).rmse;
  // The noisy pixels get 64 samples instead of ~26: about sqrt(64/26) = 1.6 times less error.
  CHECK(adaptive_rmse < uniform_rmse / 1.15);
}

TEST_CASE("adaptive: the same flags give identical pixels at 1 and 2 threads, and --aov spp holds the sample counts") {
  ScratchDir dir("adaptive-determinism");
  fs::path cornell = source_path("assets/cornell.gltf");
  std::string common = " --width 32 --height 32 --spp 256 --noise-threshold 0.05 --min-spp 8 --mode path --aov spp --quiet";
  fs::path one = dir.file("one.exr"), two = dir.file("two.exr"), again = dir.file("again.exr");
  REQUIRE(run_radiant("render " + quoted(cornell) + " -o " + quoted(one) + common + " --threads 1").exit_code == 0);
  REQUIRE(run_radiant("render " + quoted(cornell) + " -o " + quoted(two) + common + " --threads 2").exit_code == 0);
  REQUIRE(run_radiant("render " + quoted(cornell) + " -o " + quoted(again) + common + " --threads 2").exit_code == 0);
  // Pixels, not bytes: an EXR header carries the time it was written (DateTime).
  TestImage image = read_image(one);
  CHECK(image.pixels == read_image(two).pixels);
  CHECK(read_image(two).pixels == read_image(again).pixels);
  std::string png_flags = " --width 32 --height 32 --spp 256 --noise-threshold 0.05 --min-spp 8 --mode path --quiet";
  fs::path png_one = dir.file("one.png"), png_two = dir.file("two.png");
  REQUIRE(run_radiant("render " + quoted(cornell) + " -o " + quoted(png_one) + png_flags + " --threads 1").exit_code == 0);
  REQUIRE(run_radiant("render " + quoted(cornell) + " -o " + quoted(png_two) + png_flags + " --threads 2").exit_code == 0);
  CHECK(same_pixels(png_one, png_two));

  REQUIRE(image.channels == 4);
  REQUIRE(image.channel_names[3] == "spp");
  float low = 1e9f, high = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) low = std::min(low, image.at(x, y, 3)), high = std::max(high, image.at(x, y, 3));
  CHECK(low >= 8);  // --min-spp
  CHECK(high <= 256);
  CHECK(low < high);  // the counts vary: the bright light converges before the shadowed corners
}

TEST_CASE("adaptive: no pixel is left black that a uniform render at the same mean spp lights") {
  // The short block of the 128x128 Cornell box at --spp 1024 --noise-threshold 0.05: where a
  // pixel's first few samples can all miss the lamp (its indirect light is most of it).
  PreparedScene prepared = prepare_scene(load_scene(source_path("assets/cornell.gltf").string()));
  RenderOptions adaptive;
  adaptive.width = adaptive.height = 128;
  adaptive.spp = 1024;
  adaptive.mode = RenderMode::path;
  adaptive.noise_threshold = 0.05f;
  adaptive.crop = PixelWindow{64, 84, 96, 116};
  RenderResult a = render_prepared(prepared, adaptive);
  CHECK(a.stats.min_pixel_samples >= 64);  // Cycles' minimum for 0.05, as a power of two
  CHECK(a.stats.min_pixel_samples < a.stats.max_pixel_samples);  // and adaptive above it
  RenderOptions uniform = adaptive;
  uniform.noise_threshold = 0;
  uniform.spp = int(a.stats.samples / a.film.pixels.size());
  RenderResult u = render_prepared(prepared, uniform);
  int lit_by_uniform = 0, black_in_adaptive = 0;
  for (size_t i = 0; i < u.film.pixels.size(); ++i) {
    bool lit = max_component(pixel_mean(u.film.pixels[i])) > 0;
    lit_by_uniform += lit;
    black_in_adaptive += lit && max_component(pixel_mean(a.film.pixels[i])) == 0;
  }
  CHECK(lit_by_uniform == int(u.film.pixels.size()));  // every pixel of the block is lit
  CHECK(black_in_adaptive == 0);
}
