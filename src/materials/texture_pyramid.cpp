// Building mip-map pyramids: separable area-weighted box filters, charged to the budget first.
#include "materials/texture_pyramid.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "materials/surface.h"

namespace radiant {

namespace {

// One output texel's share of the input texels along an axis: input [first, first + count)
// with their weights (the overlap of each with the output's span, over the span's length).
struct AxisSpan {
  int first = 0;
  std::vector<float> weights;
};

// Output texel i of `out` covers input [i * in / out, (i + 1) * in / out).
std::vector<AxisSpan> axis_spans(int in, int out) {
  std::vector<AxisSpan> spans(static_cast<size_t>(out));
  double scale = double(in) / double(out);
  for (int i = 0; i < out; ++i) {
    double begin = i * scale, end = (i + 1) * scale;
    AxisSpan& span = spans[size_t(i)];
    span.first = int(std::floor(begin));
    for (int j = span.first; j < in && j < end; ++j)
      span.weights.push_back(float((std::min(end, j + 1.0) - std::max(begin, double(j))) / scale));
  }
  return spans;
}

// The next level from a source of `width` x `height` x `channels` read through `texel(x, y, c)`.
template <class Texel>
MipLevel downsample(int width, int height, int channels, int out_width, int out_height, const Texel& texel) {
  std::vector<AxisSpan> xs = axis_spans(width, out_width), ys = axis_spans(height, out_height);
  MipLevel level;
  level.width = out_width, level.height = out_height, level.channels = channels;
  level.texels.assign(size_t(out_width) * size_t(out_height) * size_t(channels), 0.0f);
  for (int y = 0; y < out_height; ++y)
    for (int x = 0; x < out_width; ++x)
      for (int c = 0; c < channels; ++c) {
        double sum = 0;
        const AxisSpan &sy = ys[size_t(y)], &sx = xs[size_t(x)];
        for (size_t j = 0; j < sy.weights.size(); ++j)
          for (size_t i = 0; i < sx.weights.size(); ++i)
            sum += double(sy.weights[j]) * sx.weights[i] * texel(sx.first + int(i), sy.first + int(j), c);
        level.texels[(size_t(y) * size_t(out_width) + size_t(x)) * size_t(channels) + size_t(c)] = float(sum);
      }
  return level;
}

bool image_is_usable(const ImageDesc& image) {
  if (image.width <= 0 || image.height <= 0 || image.channels < 1 || image.channels > 4) return false;
  size_t count = size_t(image.width) * size_t(image.height) * size_t(image.channels);
  return image.texels8.size() == count || image.texels_float.size() == count;
}

// Which (image, decoding) pairs the materials read: by_use's indices.
std::vector<bool> used_pyramids(const SceneDesc& scene) {
  std::vector<bool> used(scene.images.size() * 2, false);
  for (const MaterialDesc& material : scene.materials)
    for (const TextureSlot& slot : texture_slots(material)) {
      int t = slot.ref->texture;
      if (t < 0 || t >= int(scene.textures.size())) continue;
      int image = scene.textures[size_t(t)].image;
      if (image < 0 || image >= int(scene.images.size()) || !image_is_usable(scene.images[size_t(image)])) continue;
      bool srgb = slot.srgb && !scene.images[size_t(image)].texels8.empty();  // float texels have one decoding
      used[size_t(image) * 2 + (srgb ? 1 : 0)] = true;
    }
  return used;
}

uint64_t pyramid_bytes(const ImageDesc& image) {
  uint64_t texels = 0;
  for (auto [w, h] : mip_level_sizes(image.width, image.height)) texels = saturating_add(texels, uint64_t(w) * uint64_t(h));
  return saturating_multiply(texels, uint64_t(image.channels) * sizeof(float));
}

}  // namespace

const ImagePyramid* TexturePyramids::find(int image, bool srgb) const {
  size_t index = size_t(image) * 2 + (srgb ? 1 : 0);
  if (image < 0 || index >= by_use.size() || by_use[index].levels.empty()) return nullptr;
  return &by_use[index];
}

std::vector<std::pair<int, int>> mip_level_sizes(int width, int height) {
  std::vector<std::pair<int, int>> sizes;
  while (width > 1 || height > 1) {
    width = std::max(1, width / 2), height = std::max(1, height / 2);
    sizes.push_back({width, height});
  }
  return sizes;
}

ImagePyramid build_image_pyramid(const ImageDesc& image, bool srgb) {
  ImagePyramid pyramid;
  int width = image.width, height = image.height;
  for (auto [w, h] : mip_level_sizes(image.width, image.height)) {
    if (pyramid.levels.empty()) {
      pyramid.levels.push_back(downsample(width, height, image.channels, w, h, [&](int x, int y, int c) {
        return texel_value(image, x, y, c, srgb);
      }));
    } else {
      const MipLevel& above = pyramid.levels.back();
      pyramid.levels.push_back(downsample(width, height, image.channels, w, h, [&](int x, int y, int c) {
        return above.texels[(size_t(y) * size_t(above.width) + size_t(x)) * size_t(above.channels) + size_t(c)];
      }));
    }
    width = w, height = h;
  }
  return pyramid;
}

uint64_t texture_pyramid_bytes(const SceneDesc& scene) {
  std::vector<bool> used = used_pyramids(scene);
  uint64_t bytes = 0;
  for (size_t i = 0; i < used.size(); ++i)
    if (used[i]) bytes = saturating_add(bytes, pyramid_bytes(scene.images[i / 2]));
  return bytes;
}

TexturePyramids build_texture_pyramids(const SceneDesc& scene, MemoryBudget* budget) {
  TexturePyramids pyramids;
  pyramids.memory = MemoryCharge(budget, texture_pyramid_bytes(scene), scene.source_path + ": texture mip-maps");
  std::vector<bool> used = used_pyramids(scene);
  pyramids.by_use.resize(used.size());
  for (size_t i = 0; i < used.size(); ++i)
    if (used[i]) pyramids.by_use[i] = build_image_pyramid(scene.images[i / 2], i % 2 == 1);
  return pyramids;
}

bool pyramids_serve(const SceneDesc& built_for, const SceneDesc& scene) {
  if (used_pyramids(built_for) != used_pyramids(scene)) return false;
  for (size_t i = 0; i < scene.images.size(); ++i) {
    const ImageDesc &a = built_for.images[i], &b = scene.images[i];
    if (a.width != b.width || a.height != b.height || a.channels != b.channels || a.texels8 != b.texels8 ||
        a.texels_float.size() != b.texels_float.size() ||
        !std::equal(a.texels_float.begin(), a.texels_float.end(), b.texels_float.begin(),
                    [](float x, float y) { return std::memcmp(&x, &y, sizeof x) == 0; }))
      return false;
  }
  return true;
}

float mip_level_for(vec2 duv_dx, vec2 duv_dy, int width, int height, int max_level) {
  float x = std::hypot(duv_dx.x * float(width), duv_dx.y * float(height));
  float y = std::hypot(duv_dy.x * float(width), duv_dy.y * float(height));
  float rho = std::max(x, y);
  if (!(rho > 1)) return 0;  // magnified, or NaN
  return std::min(std::log2(rho), float(max_level));
}

}  // namespace radiant
