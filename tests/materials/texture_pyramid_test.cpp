// Mip-map pyramids: exact box-filtered levels, the level a footprint picks, trilinear lookups,
// the memory budget, and the footprint a camera gives a surface point.
#include <doctest/doctest.h>

#include "materials/surface.h"
#include "materials/texture_pyramid.h"
#include "render/camera.h"

namespace radiant {
namespace {

ImageDesc grey_image(int width, int height, std::vector<uint8_t> texels) {
  ImageDesc image;
  image.width = width, image.height = height, image.channels = 1;
  image.texels8 = std::move(texels);
  return image;
}

// Texel (x, y) of a single-channel level, in bytes of the source (x 255).
float level_texel(const MipLevel& level, int x, int y) { return level.texels[size_t(y * level.width + x)] * 255; }

TEST_CASE("mip levels halve each side down to 1x1, rounding down, never below 1") {
  CHECK(mip_level_sizes(8, 8) == std::vector<std::pair<int, int>>{{4, 4}, {2, 2}, {1, 1}});
  CHECK(mip_level_sizes(5, 2) == std::vector<std::pair<int, int>>{{2, 1}, {1, 1}});
  CHECK(mip_level_sizes(1, 1).empty());
}

TEST_CASE("mip levels of a 4x4 image are the exact means of its 2x2 and 4x4 blocks") {
  // Texel (x, y) = 10 y + x: block means 5.5, 7.5, 25.5, 27.5; the whole image 16.5.
  std::vector<uint8_t> texels;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) texels.push_back(uint8_t(10 * y + x));
  ImagePyramid pyramid = build_image_pyramid(grey_image(4, 4, texels), false);
  REQUIRE(pyramid.levels.size() == 2);
  const MipLevel& half = pyramid.levels[0];
  CHECK(half.width == 2);
  CHECK(level_texel(half, 0, 0) == doctest::Approx(5.5));
  CHECK(level_texel(half, 1, 0) == doctest::Approx(7.5));
  CHECK(level_texel(half, 0, 1) == doctest::Approx(25.5));
  CHECK(level_texel(half, 1, 1) == doctest::Approx(27.5));
  CHECK(level_texel(pyramid.levels[1], 0, 0) == doctest::Approx(16.5));
}

TEST_CASE("mip levels of odd sizes weigh each texel by the area it covers") {
  // 5 texels into 2: each output covers 2.5 of them, sharing the middle one.
  ImagePyramid pyramid = build_image_pyramid(grey_image(5, 1, {0, 10, 20, 30, 40}), false);
  const MipLevel& level = pyramid.levels[0];
  CHECK(level_texel(level, 0, 0) == doctest::Approx((0 + 10 + 0.5 * 20) / 2.5));
  CHECK(level_texel(level, 1, 0) == doctest::Approx((0.5 * 20 + 30 + 40) / 2.5));
  CHECK(level_texel(pyramid.levels[1], 0, 0) == doctest::Approx(20));  // the mean of all five
}

TEST_CASE("mip levels average colour in linear light: a black and white sRGB pair is 0.5, not sRGB 0.5") {
  ImageDesc image = grey_image(2, 1, {0, 255});
  CHECK(build_image_pyramid(image, true).levels[0].texels[0] == doctest::Approx(0.5f));
  ImageDesc half = grey_image(2, 1, {0, 128});
  CHECK(build_image_pyramid(half, true).levels[0].texels[0] == doctest::Approx(0.2158605f / 2));
  CHECK(build_image_pyramid(half, false).levels[0].texels[0] == doctest::Approx(128 / 255.0f / 2));
}

TEST_CASE("mip level for a footprint: log2 of its longer axis in texels, 0 when magnified") {
  // A 256 x 128 image: u steps count 256 texels, v steps 128.
  CHECK(mip_level_for({4 / 256.0f, 0}, {0, 1 / 128.0f}, 256, 128, 8) == doctest::Approx(2));
  CHECK(mip_level_for({1 / 256.0f, 0}, {0, 8 / 128.0f}, 256, 128, 8) == doctest::Approx(3));
  CHECK(mip_level_for({3 / 256.0f, 4 / 128.0f}, {0, 0}, 256, 128, 8) == doctest::Approx(std::log2(5.0f)));
  CHECK(mip_level_for({0.5f / 256, 0}, {0, 0.5f / 128}, 256, 128, 8) == 0);
  CHECK(mip_level_for({1e8f, 0}, {0, 0}, 256, 128, 8) == 8);  // at most the 1x1 level
  CHECK(mip_level_for({std::nanf(""), 0}, {0, 0}, 256, 128, 8) == 0);
}

// A scene with one texture over a 4x4 image whose columns alternate 0 and 255 (level 1 and
// below: 127.5 everywhere), and its pyramids.
struct StripedScene {
  SceneDesc scene;
  TexturePyramids pyramids;
  StripedScene() {
    std::vector<uint8_t> texels;
    for (int i = 0; i < 16; ++i) texels.push_back(i % 2 ? 255 : 0);
    scene.images.push_back(grey_image(4, 4, texels));
    scene.textures.push_back(TextureDesc{0, TextureWrap::repeat, TextureWrap::repeat, TextureFilter::nearest});
    MaterialDesc material;
    material.model = MaterialModel::metallic_roughness;
    material.metallic_roughness_texture.texture = 0;
    scene.materials.push_back(material);
    pyramids = build_texture_pyramids(scene, nullptr);
  }
  // The texel at u = 0.1 (a black column) with a footprint of `texels` texels in u.
  float value(float texels, TextureFilterMode mode) const {
    TextureLookup lookup{mode, &pyramids};
    SurfaceAttributes attributes;
    attributes.uv[0] = {0.1f, 0.1f};
    attributes.duv_dx[0] = {texels / 4, 0};
    attributes.lookup = &lookup;
    TextureRef ref;
    ref.texture = 0;
    return sample_texture(scene, ref, attributes, false).x;
  }
};

TEST_CASE("trilinear lookups blend the two levels around the footprint's, point and bilinear ignore it") {
  StripedScene striped;
  CHECK(striped.value(1, TextureFilterMode::trilinear) == 0);  // one texel: level 0
  CHECK(striped.value(2, TextureFilterMode::trilinear) == doctest::Approx(0.5f));
  CHECK(striped.value(std::sqrt(2.0f), TextureFilterMode::trilinear) == doctest::Approx(0.25f));  // level 0.5
  CHECK(striped.value(64, TextureFilterMode::trilinear) == doctest::Approx(0.5f));  // clamped to 1x1
  CHECK(striped.value(64, TextureFilterMode::bilinear) == 0);
  CHECK(striped.value(64, TextureFilterMode::point) == 0);
}

TEST_CASE("texture pyramids are built only for images a material reads, and charged first") {
  StripedScene striped;
  // 2x2 + 1x1 floats of one channel, for the linear use only.
  CHECK(texture_pyramid_bytes(striped.scene) == 5 * sizeof(float));
  CHECK(striped.pyramids.find(0, false) != nullptr);
  CHECK(striped.pyramids.find(0, true) == nullptr);
  MemoryBudget budget(5 * sizeof(float) - 1);
  CHECK_THROWS_AS(build_texture_pyramids(striped.scene, &budget), MemoryLimitError);
  CHECK(budget.used() == 0);
  SceneDesc unused = striped.scene;
  unused.materials.clear();
  CHECK(texture_pyramid_bytes(unused) == 0);
}

TEST_CASE("texture pyramids serve the next frame only when its images and their uses are the same, bit for bit") {
  StripedScene striped;
  SceneDesc next = striped.scene;
  next.meshes.clear();  // what moves does not matter to them
  CHECK(pyramids_serve(striped.scene, next));
  SceneDesc repainted = striped.scene;
  repainted.images[0].texels8[0] ^= 1;  // one bit of one texel
  CHECK_FALSE(pyramids_serve(striped.scene, repainted));
  SceneDesc unread = striped.scene;
  unread.materials.clear();
  CHECK_FALSE(pyramids_serve(striped.scene, unread));
}

TEST_CASE("a pixel's footprint: an orthographic pixel on a plane facing it, stretched on a tilted one") {
  // 2 units tall over 32 pixels: one pixel is 1/16 of a unit.
  CameraDesc camera;
  camera.projection = Projection::orthographic;
  camera.forward = {0, 0, -1}, camera.up = {0, 1, 0}, camera.ortho_height = 2;
  PixelSpread spread = make_pixel_spread(make_camera_frame(camera, 32, 32));
  vec3 dpdx, dpdy;
  approximate_dp_dxy(spread, {0.3f, 0.2f, -5}, {0, 0, 1}, dpdx, dpdy);
  CHECK(length(dpdx) == doctest::Approx(1 / 16.0f));
  CHECK(length(dpdy) == doctest::Approx(1 / 16.0f));
  CHECK(std::abs(dpdx.x) == doctest::Approx(1 / 16.0f));
  // A plane tilted 60 degrees about x: a pixel in y covers 1/16 / cos(60) of it.
  vec3 tilted = {0, std::sin(pi / 3), std::cos(pi / 3)};
  approximate_dp_dxy(spread, {0, 0, -5}, tilted, dpdx, dpdy);
  CHECK(length(dpdx) == doctest::Approx(1 / 16.0f));
  CHECK(length(dpdy) == doctest::Approx(1 / 8.0f));
}

TEST_CASE("a pixel's footprint: a pinhole's grows with distance") {
  CameraDesc camera;
  camera.forward = {0, 0, -1}, camera.up = {0, 1, 0}, camera.vertical_fov_degrees = 90;
  PixelSpread spread = make_pixel_spread(make_camera_frame(camera, 64, 64));
  vec3 near_x, near_y, far_x, far_y;
  approximate_dp_dxy(spread, {0, 0, -1}, {0, 0, 1}, near_x, near_y);
  approximate_dp_dxy(spread, {0, 0, -10}, {0, 0, 1}, far_x, far_y);
  // A 90-degree view is 2 units wide at distance 1: 1/32 a pixel at the centre, less at the
  // corners, whose spread the approximation takes (the smallest over the image).
  CHECK(length(near_x) <= 1 / 32.0f);
  CHECK(length(near_x) > 1 / 128.0f);
  CHECK(length(far_x) == doctest::Approx(10 * length(near_x)).epsilon(1e-3));
}

TEST_CASE("a sample's share of the footprint: all of it first, then 1/sqrt(index + 1), never below an eighth") {
  CHECK(texture_footprint_scale(0) == 1.0f);
  CHECK(texture_footprint_scale(3) == 0.5f);
  CHECK(texture_footprint_scale(15) == 0.25f);
  CHECK(texture_footprint_scale(63) == 0.125f);
  CHECK(texture_footprint_scale(1u << 30) == 0.125f);
  for (uint32_t i = 0; i < 100; ++i) CHECK(texture_footprint_scale(i + 1) <= texture_footprint_scale(i));
}

}  // namespace
}  // namespace radiant
