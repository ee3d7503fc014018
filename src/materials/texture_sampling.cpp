// Texture lookups: KHR_texture_transform, wrap modes, nearest/bilinear/trilinear filtering, sRGB decode.
#include <cmath>

#include "materials/surface.h"
#include "materials/texture_pyramid.h"

namespace radiant {

const std::array<float, 256>& srgb_to_linear_table() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> values{};
    for (int i = 0; i < 256; ++i) {
      double c = i / 255.0;
      values[i] = float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
    }
    return values;
  }();
  return table;
}

const ImageDesc* texture_image(const SceneDesc& scene, const TextureRef& ref) {
  if (ref.texture < 0 || ref.texture >= int(scene.textures.size())) return nullptr;
  int index = scene.textures[ref.texture].image;
  if (index < 0 || index >= int(scene.images.size())) return nullptr;
  const ImageDesc& image = scene.images[index];
  if (image.width <= 0 || image.height <= 0 || image.channels < 1 || image.channels > 4) return nullptr;
  size_t count = size_t(image.width) * size_t(image.height) * size_t(image.channels);
  if (image.texels8.size() != count && image.texels_float.size() != count) return nullptr;
  return &image;
}

vec2 transform_uv(const TextureRef& ref, vec2 uv) {
  if (ref.rotation == 0 && ref.scale.x == 1 && ref.scale.y == 1 && ref.offset.x == 0 && ref.offset.y == 0)
    return uv;
  float c = std::cos(ref.rotation), s = std::sin(ref.rotation);
  vec2 scaled = {uv.x * ref.scale.x, uv.y * ref.scale.y};
  return {c * scaled.x + s * scaled.y + ref.offset.x, -s * scaled.x + c * scaled.y + ref.offset.y};
}

namespace {

// Brings a texture coordinate into a small range with the same texels, so that NaN or huge
// values can never produce an out-of-range integer.
float reduce_coordinate(float t, TextureWrap wrap) {
  if (!std::isfinite(t)) return 0;
  switch (wrap) {
    case TextureWrap::repeat: return t - std::floor(t);
    case TextureWrap::mirrored_repeat: return t - 2 * std::floor(t / 2);
    case TextureWrap::clamp_to_edge: return std::clamp(t, -1.0f, 2.0f);
  }
  return 0;
}

}  // namespace

int wrap_index(int i, int size, TextureWrap wrap) {
  // Inside the image every mode keeps the index: the common case, without the divisions below.
  if (unsigned(i) < unsigned(size)) return i;
  switch (wrap) {
    case TextureWrap::repeat: return ((i % size) + size) % size;
    case TextureWrap::clamp_to_edge: return std::clamp(i, 0, size - 1);
    case TextureWrap::mirrored_repeat: {
      int period = 2 * size;
      int m = ((i % period) + period) % period;
      return m < size ? m : period - 1 - m;
    }
  }
  return 0;
}

namespace {

// RGBA from a texel's channel values (missing channels: RGB repeat the first, A = 1).
vec4 expand_channels(const float* values, int channels) {
  switch (channels) {
    case 1: return {values[0], values[0], values[0], 1};
    case 2: return {values[0], values[0], values[0], values[1]};
    case 3: return {values[0], values[1], values[2], 1};
    default: return {values[0], values[1], values[2], values[3]};
  }
}

// One texel as linear RGBA; the alpha channel is always linear. texel_value's numbers, with the
// texel's address and the storage's kind found once for its channels.
vec4 fetch_texel(const ImageDesc& image, int x, int y, bool srgb) {
  float values[4] = {0, 0, 0, 1};
  int channels = image.channels;
  size_t first = (size_t(y) * size_t(image.width) + size_t(x)) * size_t(channels);
  if (image.texels8.empty()) {
    for (int c = 0; c < channels; ++c) values[c] = image.texels_float[first + c];
  } else {
    const uint8_t* bytes = &image.texels8[first];
    const std::array<float, 256>& decode = srgb_to_linear_table();
    int alpha = channels == 2 ? 1 : 3;
    for (int c = 0; c < channels; ++c) values[c] = srgb && c != alpha ? decode[bytes[c]] : bytes[c] / 255.0f;
  }
  return expand_channels(values, channels);
}

vec4 mix(vec4 a, vec4 b, float t) {
  return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t, a.w + (b.w - a.w) * t};
}

// One level of a texture to read: level 0 (the image itself) or a pyramid level.
struct LevelView {
  const ImageDesc* image = nullptr;
  const MipLevel* level = nullptr;  // null: level 0
  int width = 0, height = 0;
  bool srgb = false;

  vec4 fetch(int x, int y) const {
    if (!level) return fetch_texel(*image, x, y, srgb);
    return expand_channels(&level->texels[(size_t(y) * size_t(width) + size_t(x)) * size_t(level->channels)],
                           level->channels);
  }
};

LevelView level_view(const ImageDesc& image, const ImagePyramid* pyramid, int level, bool srgb) {
  if (level == 0 || !pyramid) return {&image, nullptr, image.width, image.height, srgb};
  const MipLevel& m = pyramid->levels[size_t(level - 1)];
  return {&image, &m, m.width, m.height, srgb};
}

// The nearest texel or the bilinear mean of the four texel centres around uv, on one level.
vec4 lookup_level(const LevelView& view, const TextureDesc& texture, vec2 uv, bool nearest) {
  // glTF puts uv (0,0) at the top-left texel, the first row in memory: no vertical flip.
  float x = reduce_coordinate(uv.x, texture.wrap_s) * float(view.width);
  float y = reduce_coordinate(uv.y, texture.wrap_t) * float(view.height);
  if (nearest) {
    int i = wrap_index(int(std::floor(x)), view.width, texture.wrap_s);
    int j = wrap_index(int(std::floor(y)), view.height, texture.wrap_t);
    return view.fetch(i, j);
  }
  // Bilinear between the four texel centres around (x, y); centres sit at half-integers.
  float fx = x - 0.5f, fy = y - 0.5f;
  int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
  float tx = fx - float(x0), ty = fy - float(y0);
  int i0 = wrap_index(x0, view.width, texture.wrap_s);
  int i1 = wrap_index(x0 + 1, view.width, texture.wrap_s);
  int j0 = wrap_index(y0, view.height, texture.wrap_t);
  int j1 = wrap_index(y0 + 1, view.height, texture.wrap_t);
  vec4 top = mix(view.fetch(i0, j0), view.fetch(i1, j0), tx);
  vec4 bottom = mix(view.fetch(i0, j1), view.fetch(i1, j1), tx);
  return mix(top, bottom, ty);
}

// KHR_texture_transform's linear part (R * S) applied to a uv difference.
vec2 transform_uv_difference(const TextureRef& ref, vec2 d) {
  if (ref.rotation == 0 && ref.scale.x == 1 && ref.scale.y == 1) return d;
  float c = std::cos(ref.rotation), s = std::sin(ref.rotation);
  vec2 scaled = {d.x * ref.scale.x, d.y * ref.scale.y};
  return {c * scaled.x + s * scaled.y, -s * scaled.x + c * scaled.y};
}

}  // namespace

float texel_value(const ImageDesc& image, int x, int y, int c, bool srgb) {
  size_t index = (size_t(y) * size_t(image.width) + size_t(x)) * size_t(image.channels) + size_t(c);
  if (image.texels8.empty()) return image.texels_float[index];
  uint8_t byte = image.texels8[index];
  bool is_alpha = image.channels == 2 ? c == 1 : c == 3;
  return srgb && !is_alpha ? srgb_to_linear_table()[byte] : byte / 255.0f;
}

vec4 sample_texture(const SceneDesc& scene, const TextureRef& ref, const SurfaceAttributes& attributes,
                    bool srgb) {
  const ImageDesc* image = texture_image(scene, ref);
  if (!image || ref.texcoord < 0 || ref.texcoord > 1) return {1, 1, 1, 1};
  const TextureDesc& texture = scene.textures[ref.texture];
  vec2 uv = transform_uv(ref, attributes.uv[ref.texcoord]);
  TextureFilterMode mode = attributes.lookup ? attributes.lookup->mode : TextureFilterMode::bilinear;
  bool nearest = mode == TextureFilterMode::point || texture.filter == TextureFilter::nearest;
  const ImagePyramid* pyramid = nullptr;
  if (mode == TextureFilterMode::trilinear && attributes.lookup->pyramids)
    pyramid = attributes.lookup->pyramids->find(texture.image, srgb && !image->texels8.empty());
  if (!pyramid) return lookup_level(level_view(*image, nullptr, 0, srgb), texture, uv, nearest);
  // Trilinear: the two levels around the footprint's, each read with the texture's own filter.
  float level = mip_level_for(transform_uv_difference(ref, attributes.duv_dx[ref.texcoord]),
                              transform_uv_difference(ref, attributes.duv_dy[ref.texcoord]), image->width,
                              image->height, int(pyramid->levels.size()));
  int lower = int(level);
  vec4 value = lookup_level(level_view(*image, pyramid, lower, srgb), texture, uv, nearest);
  float t = level - float(lower);
  if (t == 0) return value;
  return mix(value, lookup_level(level_view(*image, pyramid, lower + 1, srgb), texture, uv, nearest), t);
}

vec2 sample_texture_slope(const SceneDesc& scene, const TextureRef& ref, const SurfaceAttributes& attributes) {
  const ImageDesc* image = texture_image(scene, ref);
  if (!image || ref.texcoord < 0 || ref.texcoord > 1) return {0, 0};
  vec2 step = {0.5f / float(image->width), 0.5f / float(image->height)};
  auto height_at = [&](vec2 offset) {
    SurfaceAttributes moved = attributes;
    moved.uv[ref.texcoord] = attributes.uv[ref.texcoord] + offset;
    return sample_texture(scene, ref, moved, false).x;
  };
  float du = height_at({step.x, 0}) - height_at({-step.x, 0});
  float dv = height_at({0, step.y}) - height_at({0, -step.y});
  return {du / (2 * step.x), dv / (2 * step.y)};
}

}  // namespace radiant
