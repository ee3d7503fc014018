// Filtered textures in renders: a checkerboard floor at grazing angles converges to its mean grey
// at one sample per pixel when mip-mapped, and shimmers without; the image stays independent of
// threads and crops.
#include <doctest/doctest.h>

#include <cmath>

#include "support/scene_builders.h"

namespace radiant {
namespace {

using test::render_scene;

// A 40 x 40 floor at y = 0 under an unlit (emitting its base colour) checkerboard of 8x8 texels,
// one texel per 1/64 unit, seen from 1 unit above looking 20 degrees down: every pixel covers
// several texels, so the exact pixel value is the checkerboard's mean, 0.5 in linear light.
SceneDesc grazing_checkerboard() {
  SceneDesc scene;
  ImageDesc image;
  image.width = image.height = 8, image.channels = 1;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) image.texels8.push_back((x + y) % 2 ? 255 : 0);
  scene.images.push_back(image);
  scene.textures.push_back(TextureDesc{0});
  MaterialDesc material;
  material.model = MaterialModel::metallic_roughness;
  material.unlit = true;
  material.base_color_texture.texture = 0;
  int m = test::add_material(scene, material);
  MeshDesc mesh;
  mesh.material = m;
  float half = 20, uv_per_unit = 8;  // 8 texels a uv unit: 64 texels a unit
  mesh.positions = {{-half, 0, -half}, {-half, 0, half}, {half, 0, half}, {half, 0, -half}};
  for (const vec3& p : mesh.positions) mesh.texcoords0.push_back({p.x * uv_per_unit, p.z * uv_per_unit});
  mesh.indices = {0, 1, 2, 0, 2, 3};
  scene.meshes.push_back(mesh);
  scene.instances.push_back(InstanceDesc{0});
  float pitch = 20 * pi / 180;
  scene.cameras.push_back(
      test::perspective_camera({0, 1, 0}, {0, -std::sin(pitch), -std::cos(pitch)}, {0, 1, 0}, 30));
  return scene;
}

RenderOptions one_sample(TextureFilterMode filter) {
  RenderOptions o;
  o.width = o.height = 32;
  o.spp = 1;
  o.mode = RenderMode::path;
  o.texture_filter = filter;
  o.quiet = true;
  return o;
}

// Mean |pixel - 0.5| over the far (upper) half of the image.
double far_half_error(const Film& film) {
  double sum = 0;
  for (int y = 0; y < film.height / 2; ++y)
    for (int x = 0; x < film.width; ++x) sum += std::abs(pixel_mean(film.at(x, y)).x - 0.5);
  return sum / (film.width * film.height / 2);
}

TEST_CASE("texture filtering: a grazing checkerboard is its mean grey at 1 spp with trilinear, noise without") {
  SceneDesc scene = grazing_checkerboard();
  double trilinear = far_half_error(render_scene(scene, one_sample(TextureFilterMode::trilinear)).film);
  double bilinear = far_half_error(render_scene(scene, one_sample(TextureFilterMode::bilinear)).film);
  double point = far_half_error(render_scene(scene, one_sample(TextureFilterMode::point)).film);
  CHECK(trilinear < 0.02);
  // Bilinear between black and white texel centres at a uniform point: E|f - 0.5| = 1/8.
  CHECK(bilinear > 0.08);
  CHECK(point > 0.3);  // each sample sees black or white: E|f - 0.5| = 1/2
}

TEST_CASE("texture filtering: the same image at any thread count and in any crop") {
  SceneDesc scene = grazing_checkerboard();
  RenderOptions o = one_sample(TextureFilterMode::trilinear);
  o.spp = 2;
  o.threads = 1;
  Film one = render_scene(scene, o).film;
  o.threads = 3;
  Film three = render_scene(scene, o).film;
  o.crop = PixelWindow{5, 7, 21, 30};
  Film crop = render_scene(scene, o).film;
  for (size_t i = 0; i < one.pixels.size(); ++i) REQUIRE(pixel_mean(one.pixels[i]) == pixel_mean(three.pixels[i]));
  for (int y = 7; y < 30; ++y)
    for (int x = 5; x < 21; ++x) REQUIRE(pixel_mean(crop.at(x - 5, y - 7)) == pixel_mean(one.at(x, y)));
}

}  // namespace
}  // namespace radiant
