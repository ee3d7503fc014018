// Texture lookups: texel addressing (glTF top-left origin), filters, wrap modes, sRGB decode,
// channel expansion and KHR_texture_transform.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "materials/surface.h"

namespace radiant {
namespace {

// A scene with one texture over one 8-bit image of `width` x `height` x `channels`.
SceneDesc scene_with_image(int width, int height, int channels, std::vector<uint8_t> texels,
                           TextureFilter filter = TextureFilter::nearest,
                           TextureWrap wrap = TextureWrap::repeat) {
  SceneDesc scene;
  ImageDesc image;
  image.width = width, image.height = height, image.channels = channels;
  image.texels8 = std::move(texels);
  scene.images.push_back(image);
  TextureDesc texture;
  texture.image = 0;
  texture.filter = filter;
  texture.wrap_s = texture.wrap_t = wrap;
  scene.textures.push_back(texture);
  return scene;
}

// A 2x2 single-channel image: row 0 (top) is 0 10, row 1 is 20 30.
SceneDesc two_by_two(TextureFilter filter, TextureWrap wrap = TextureWrap::repeat) {
  return scene_with_image(2, 2, 1, {0, 10, 20, 30}, filter, wrap);
}

float grey_at(const SceneDesc& scene, vec2 uv, TextureRef ref = {}) {
  ref.texture = 0;
  SurfaceAttributes attributes;
  attributes.uv[0] = uv;
  return sample_texture(scene, ref, attributes, false).x * 255;
}

TEST_CASE("texture nearest: uv (0,0) is the top-left texel, the first row in memory") {
  SceneDesc scene = two_by_two(TextureFilter::nearest);
  CHECK(grey_at(scene, {0.25f, 0.25f}) == doctest::Approx(0));
  CHECK(grey_at(scene, {0.75f, 0.25f}) == doctest::Approx(10));
  CHECK(grey_at(scene, {0.25f, 0.75f}) == doctest::Approx(20));
  CHECK(grey_at(scene, {0.99f, 0.99f}) == doctest::Approx(30));
}

TEST_CASE("texture bilinear: texel centres are exact, midpoints average") {
  SceneDesc scene = two_by_two(TextureFilter::linear, TextureWrap::clamp_to_edge);
  CHECK(grey_at(scene, {0.25f, 0.25f}) == doctest::Approx(0));
  CHECK(grey_at(scene, {0.75f, 0.75f}) == doctest::Approx(30));
  CHECK(grey_at(scene, {0.5f, 0.25f}) == doctest::Approx(5));
  CHECK(grey_at(scene, {0.25f, 0.5f}) == doctest::Approx(10));
  CHECK(grey_at(scene, {0.5f, 0.5f}) == doctest::Approx(15));
  CHECK(grey_at(scene, {0.375f, 0.25f}) == doctest::Approx(2.5));
}

TEST_CASE("texture wrap: repeat, clamp to edge and mirrored repeat") {
  SceneDesc repeat = two_by_two(TextureFilter::nearest, TextureWrap::repeat);
  CHECK(grey_at(repeat, {1.25f, 0.25f}) == doctest::Approx(0));
  CHECK(grey_at(repeat, {-0.25f, 0.25f}) == doctest::Approx(10));
  CHECK(grey_at(repeat, {0.25f, -0.25f}) == doctest::Approx(20));
  SceneDesc clamp = two_by_two(TextureFilter::nearest, TextureWrap::clamp_to_edge);
  CHECK(grey_at(clamp, {1.5f, 0.25f}) == doctest::Approx(10));
  CHECK(grey_at(clamp, {-3.0f, 0.25f}) == doctest::Approx(0));
  CHECK(grey_at(clamp, {0.25f, 7.0f}) == doctest::Approx(20));
  SceneDesc mirrored = two_by_two(TextureFilter::nearest, TextureWrap::mirrored_repeat);
  CHECK(grey_at(mirrored, {1.25f, 0.25f}) == doctest::Approx(10));  // the mirror image starts at u = 1
  CHECK(grey_at(mirrored, {1.75f, 0.25f}) == doctest::Approx(0));
  CHECK(grey_at(mirrored, {2.25f, 0.25f}) == doctest::Approx(0));   // period 2
  CHECK(grey_at(mirrored, {-0.25f, 0.25f}) == doctest::Approx(0));
  // Bilinear across the u = 0 edge blends with the far column only when repeating.
  vec2 left_edge = {0, 0.25f};
  CHECK(grey_at(two_by_two(TextureFilter::linear, TextureWrap::repeat), left_edge) == doctest::Approx(5));
  CHECK(grey_at(two_by_two(TextureFilter::linear, TextureWrap::clamp_to_edge), left_edge) == 0);
  CHECK(grey_at(two_by_two(TextureFilter::linear, TextureWrap::mirrored_repeat), left_edge) == 0);
}

TEST_CASE("texture sRGB: 8-bit color decodes through the sRGB curve, alpha stays linear") {
  SceneDesc scene = scene_with_image(1, 1, 4, {128, 255, 0, 128});
  TextureRef ref;
  ref.texture = 0;
  vec4 srgb = sample_texture(scene, ref, {}, true);
  CHECK(srgb.x == doctest::Approx(0.2158605f).epsilon(1e-6));
  CHECK(srgb.y == 1.0f);
  CHECK(srgb.z == 0.0f);
  CHECK(srgb.w == doctest::Approx(128 / 255.0f));
  vec4 linear = sample_texture(scene, ref, {}, false);
  CHECK(linear.x == doctest::Approx(128 / 255.0f));
}

TEST_CASE("texture channels: grey, grey+alpha and RGB expand to RGBA") {
  TextureRef ref;
  ref.texture = 0;
  vec4 grey = sample_texture(scene_with_image(1, 1, 1, {51}), ref, {}, false);
  CHECK(grey.x == doctest::Approx(0.2f));
  CHECK(grey.z == doctest::Approx(0.2f));
  CHECK(grey.w == 1.0f);
  vec4 grey_alpha = sample_texture(scene_with_image(1, 1, 2, {51, 102}), ref, {}, true);
  CHECK(grey_alpha.y == grey_alpha.x);
  CHECK(grey_alpha.w == doctest::Approx(0.4f));
  vec4 rgb = sample_texture(scene_with_image(1, 1, 3, {51, 102, 153}), ref, {}, false);
  CHECK(rgb.z == doctest::Approx(0.6f));
  CHECK(rgb.w == 1.0f);
}

TEST_CASE("texture float texels are returned as stored, even when sRGB is asked") {
  SceneDesc scene = scene_with_image(1, 1, 3, {});
  scene.images[0].texels_float = {2.5f, 0.5f, 0.25f};
  TextureRef ref;
  ref.texture = 0;
  vec4 texel = sample_texture(scene, ref, {}, true);
  CHECK(texel.x == 2.5f);
  CHECK(texel.y == 0.5f);
  CHECK(texel.z == 0.25f);
  CHECK(texel.w == 1.0f);
}

// A 4x4 image whose texel (x, y) holds 10 * y + x, to read back where a lookup landed.
SceneDesc numbered_four_by_four() {
  std::vector<uint8_t> texels;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) texels.push_back(uint8_t(10 * y + x));
  return scene_with_image(4, 4, 1, texels);
}

TEST_CASE("texture transform: KHR_texture_transform applies scale, then rotation, then offset") {
  SceneDesc scene = numbered_four_by_four();
  TextureRef offset;
  offset.offset = {0.5f, 0};
  CHECK(grey_at(scene, {0.1f, 0.1f}, offset) == doctest::Approx(2));  // uv' = (0.6, 0.1)
  TextureRef scale;
  scale.scale = {2, 3};
  CHECK(grey_at(scene, {0.3f, 0.2f}, scale) == doctest::Approx(22));  // uv' = (0.6, 0.6)
  // The extension's example: offset (0, 1), rotation pi/2, scale 0.5.
  TextureRef example;
  example.offset = {0, 1};
  example.rotation = 1.57079632679f;
  example.scale = {0.5f, 0.5f};
  CHECK(grey_at(scene, {0.25f, 0.5f}, example) == doctest::Approx(31));  // uv' = (0.25, 0.875)
  CHECK(grey_at(scene, {0.9f, 0.1f}, example) == doctest::Approx(20));   // uv' = (0.05, 0.55)
}

TEST_CASE("texture coordinates: the ref's texcoord picks the UV set") {
  SceneDesc scene = two_by_two(TextureFilter::nearest);
  TextureRef ref;
  ref.texture = 0;
  ref.texcoord = 1;
  SurfaceAttributes attributes;
  attributes.uv[0] = {0.25f, 0.25f};
  attributes.uv[1] = {0.75f, 0.75f};
  CHECK(sample_texture(scene, ref, attributes, false).x * 255 == doctest::Approx(30));
}

TEST_CASE("texture robustness: invalid refs are white, hostile uvs stay inside the image") {
  SceneDesc scene = two_by_two(TextureFilter::linear);
  SurfaceAttributes attributes;
  TextureRef missing;
  CHECK(sample_texture(scene, missing, attributes, false).x == 1.0f);
  TextureRef out_of_range;
  out_of_range.texture = 3;
  CHECK(sample_texture(scene, out_of_range, attributes, false).y == 1.0f);
  TextureRef bad_set;
  bad_set.texture = 0, bad_set.texcoord = 2;
  CHECK(sample_texture(scene, bad_set, attributes, false).z == 1.0f);
  SceneDesc truncated = scene;
  truncated.images[0].texels8.pop_back();  // fewer texels than width * height * channels
  TextureRef ref;
  ref.texture = 0;
  CHECK(sample_texture(truncated, ref, attributes, false).w == 1.0f);
  float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  for (TextureWrap wrap : {TextureWrap::repeat, TextureWrap::clamp_to_edge, TextureWrap::mirrored_repeat}) {
    for (TextureFilter filter : {TextureFilter::nearest, TextureFilter::linear}) {
      SceneDesc hostile = two_by_two(filter, wrap);
      for (vec2 uv : {vec2{nan, 0.5f}, vec2{inf, -inf}, vec2{1e30f, -1e30f}, vec2{-2.5e9f, 3e9f}}) {
        float value = grey_at(hostile, uv);
        CHECK(value >= 0);
        CHECK(value <= 30);
      }
    }
  }
}

}  // namespace
}  // namespace radiant
