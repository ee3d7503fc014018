// The denoiser against scenes whose answer is known or rendered with many samples: it converges
// to the analytic value, keeps texture edges, and gives the same bits on any number of threads.
#include <doctest/doctest.h>

#include <tbb/task_arena.h>

#include <cmath>

#include "denoise/denoise.h"
#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

RenderOptions denoise_options(int size, int spp, uint32_t seed = 0) {
  RenderOptions o;
  o.width = o.height = size;
  o.spp = spp;
  o.mode = RenderMode::path;
  o.seed = seed;
  o.denoise = true;
  o.quiet = true;
  return o;
}

std::vector<color3> raw_image(const Film& film) {
  std::vector<color3> image;
  for (const FilmPixel& p : film.pixels) image.push_back(pixel_mean(p));
  return image;
}

std::vector<color3> denoised_image(const Film& film, int threads = 0) {
  std::vector<color3> out;
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] { out = denoise_film(film, nullptr, "test"); });
  return out;
}

// Mean squared difference of `image` from `reference` over the pixels `mask` keeps (all without one).
double mean_squared_error(const std::vector<color3>& image, const std::vector<color3>& reference,
                          const std::vector<bool>& mask = {}) {
  double sum = 0;
  size_t count = 0;
  for (size_t i = 0; i < image.size(); ++i) {
    if (!mask.empty() && !mask[i]) continue;
    for (int c = 0; c < 3; ++c) sum += double(image[i][c] - reference[i][c]) * (image[i][c] - reference[i][c]);
    count += 3;
  }
  return sum / double(count);
}

// Inside a closed diffuse sphere of albedo 0.5 with a point light of intensity pi at its centre,
// every point shows radiance 1 (0.5 direct, as much again from the bounces): a uniformly lit
// surface whose paths still vary from sample to sample.
SceneDesc lit_sphere_inside() {
  SceneDesc scene;
  add_sphere(scene, {0, 0, 0}, 1, add_diffuse(scene, {0.5f, 0.5f, 0.5f}));
  scene.lights.push_back(point_light({0, 0, 0}, {pi, pi, pi}));
  scene.cameras.push_back(perspective_camera({0.1f, 0.2f, 0.3f}, {0, 0, -1}, {0, 1, 0}, 60));
  return scene;
}

// A floor with a checkerboard base colour (0.8 and 0.1, one check 8 pixels wide at 64x64) seen
// straight down, lit by a uniform sky (checker_options) that a sphere above it shades softly.
SceneDesc checker_floor() {
  SceneDesc scene;
  ImageDesc image;
  image.width = image.height = 64, image.channels = 1;  // a texel a pixel: the checks' edges stay sharp
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) image.texels8.push_back((x / 8 + y / 8) % 2 ? 230 : 90);  // sRGB: ~0.8 and ~0.1
  scene.images.push_back(image);
  scene.textures.push_back(TextureDesc{0});
  MaterialDesc material;
  material.model = MaterialModel::metallic_roughness;
  material.roughness = 1;
  material.base_color_texture.texture = 0;
  int floor = add_material(scene, material);
  MeshDesc mesh;
  mesh.material = floor;
  mesh.positions = {{-4, 0, -4}, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4}};
  for (const vec3& p : mesh.positions) mesh.texcoords0.push_back({(p.x + 4) / 8, (p.z + 4) / 8});
  mesh.indices = {0, 1, 2, 0, 2, 3};
  scene.meshes.push_back(mesh);
  scene.instances.push_back(InstanceDesc{0});
  add_sphere(scene, {0.6f, 1.2f, 0.4f}, 0.5f, add_diffuse(scene, {0.5f, 0.5f, 0.5f}));
  scene.cameras.push_back(ortho_camera({0, 5, 0}, {0, -1, 0}, {0, 0, -1}, 8));
  return scene;
}

RenderOptions checker_options(int size, int spp, uint32_t seed = 0) {
  RenderOptions o = denoise_options(size, spp, seed);
  o.env_color = color3{1, 1, 1};
  return o;
}

}  // namespace

TEST_CASE("denoise: a uniformly lit surface converges to its analytic radiance with far less variance than raw") {
  RenderOptions o = denoise_options(32, 16);
  o.max_depth = 1000;
  RenderResult r = render_scene(lit_sphere_inside(), o);
  std::vector<color3> raw = raw_image(r.film), denoised = denoised_image(r.film);
  std::vector<color3> exact(raw.size(), color3{1, 1, 1});
  double mean = 0;
  for (const color3& c : denoised) mean += (c.x + c.y + c.z) / 3;
  mean /= double(denoised.size());
  double raw_error = mean_squared_error(raw, exact), denoised_error = mean_squared_error(denoised, exact);
  CAPTURE(raw_error);
  CAPTURE(denoised_error);
  CHECK(mean == doctest::Approx(1.0).epsilon(0.03));
  CHECK(denoised_error < raw_error / 8);
}

// The edge bound is raw 32 spp's, not 64's: at 16 spp the albedo of a pixel a check's edge crosses
// still carries the noise of which side its samples fell on, and the fit follows it (docs/denoise.md).
TEST_CASE("denoise: a textured checkerboard keeps its edges: at 16 spp its edge error is at most raw 32 spp's") {
  SceneDesc scene = checker_floor();
  RenderResult reference = render_scene(scene, checker_options(64, 1024, 7));
  std::vector<color3> truth = raw_image(reference.film);
  // The pixels beside a check's edge: their albedo differs from a neighbour's by more than 0.2.
  std::vector<bool> edge(truth.size(), false);
  int edges = 0;
  for (int y = 1; y < 63; ++y)
    for (int x = 1; x < 63; ++x) {
      float albedo = pixel_albedo(reference.film.at(x, y), reference.film.aovs[size_t(y) * 64 + x]).x;
      for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        size_t j = size_t(y + dy) * 64 + x + dx;
        if (std::abs(pixel_albedo(reference.film.pixels[j], reference.film.aovs[j]).x - albedo) > 0.2f) {
          edge[size_t(y) * 64 + x] = true;
          break;
        }
      }
      edges += edge[size_t(y) * 64 + x];
    }
  REQUIRE(edges > 400);
  std::vector<color3> raw16 = raw_image(render_scene(scene, checker_options(64, 16)).film);
  std::vector<color3> denoised16 = denoised_image(render_scene(scene, checker_options(64, 16)).film);
  std::vector<color3> raw32 = raw_image(render_scene(scene, checker_options(64, 32, 1)).film);
  double edge_denoised = mean_squared_error(denoised16, truth, edge), edge_raw32 = mean_squared_error(raw32, truth, edge);
  double all_denoised = mean_squared_error(denoised16, truth), all_raw16 = mean_squared_error(raw16, truth);
  CAPTURE(edge_denoised);
  CAPTURE(edge_raw32);
  CAPTURE(all_denoised);
  CAPTURE(all_raw16);
  CHECK(edge_denoised <= edge_raw32);
  CHECK(all_denoised < all_raw16 / 4);
}

TEST_CASE("denoise: the same bits on one thread and on several") {
  RenderResult r = render_scene(checker_floor(), checker_options(40, 8));
  std::vector<color3> one = denoised_image(r.film, 1), three = denoised_image(r.film, 3);
  REQUIRE(one.size() == three.size());
  size_t different = 0;
  for (size_t i = 0; i < one.size(); ++i) different += !(one[i] == three[i]);
  CHECK(different == 0);
}

TEST_CASE("denoise: the film's half images split the samples by index and change no pixel") {
  RenderOptions o = checker_options(16, 6);
  RenderResult with_halves = render_scene(checker_floor(), o);
  o.denoise = false;
  RenderResult without = render_scene(checker_floor(), o);
  REQUIRE(with_halves.film.odd_half.size() == 16 * 16);
  CHECK(without.film.odd_half.empty());
  for (size_t i = 0; i < with_halves.film.pixels.size(); ++i) {
    const FilmPixel& p = with_halves.film.pixels[i];
    CHECK(p.sum[0] == without.film.pixels[i].sum[0]);
    CHECK(with_halves.film.odd_half[i].samples == 3);
    color3 even, odd;
    pixel_half_means(p, with_halves.film.odd_half[i], even, odd);
    CHECK(((even + odd) * 0.5f).x == doctest::Approx(pixel_mean(p).x).epsilon(1e-5));
  }
}

TEST_CASE("denoise: the working memory is charged before it is taken, and a small budget refuses it") {
  RenderResult r = render_scene(checker_floor(), checker_options(32, 4));
  MemoryBudget budget(denoise_bytes(32, 32, 1) / 2);
  CHECK_THROWS_AS(tbb::task_arena(1).execute([&] { denoise_film(r.film, &budget, "floor"); }), MemoryLimitError);
  CHECK(budget.used() == 0);
}
